// frame_plan.hpp — which frames an animation along a camera path has, and where a folder of
// numbered PNGs keeps them.
//
// A path from start_s to end_s at `fps` frames per second has floor(duration x fps) + 1 frames:
// frame i shows time start_s + i / fps, so frame 0 is the opening keyframe and, when duration x
// fps is whole, the last frame is the closing keyframe (a 2 s path at 24 fps: 49 frames; as a
// video, 49 / 24 = 2.04 s, since every frame is shown for 1 / fps).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fr {

// More frames than this is a mistake (a path of 11.5 hours at 24 fps), refused before rendering.
constexpr int kMaxAnimationFrames = 1000000;

struct AnimationFrames {
  double start_s = 0;
  int fps = 0;
  int frames = 0;
  double time_s(int frame) const { return start_s + static_cast<double>(frame) / fps; }
  // True when the last frame falls before the closing keyframe (duration x fps not whole).
  bool ends_early = false;
};

// The plan for a path of [start_s, end_s] at `fps`, or nullopt with *problem when it has more
// than kMaxAnimationFrames frames.
std::optional<AnimationFrames> plan_frames(double start_s, double end_s, int fps,
                                           std::string* problem);

// "frame_000042.png": six digits hold kMaxAnimationFrames frames, and names sort by number.
std::string frame_file_name(int frame);

// A PNG sequence folder records what it holds in a small file beside the frames, so that an
// interrupted run resumes only the same animation: every line "key = value" of `identity` (the
// scene, the path file's digest, fps, size, settings and options) must match.
using AnimationIdentity = std::vector<std::pair<std::string, std::string>>;
constexpr const char* kSequenceRecordName = ".fractalis-animation";

struct SequenceState {
  std::vector<bool> frame_done;  // per frame: a whole PNG of the right size is there
  int done = 0;
};

// Makes `folder` ready for the sequence: creates it (its parent must exist), and checks a
// folder that exists: with `force`, its frames and record are removed; without, its record must
// match `identity` (a folder without a record must hold no frames). Writes the record. Returns
// the frames already done, or nullopt with *problem (naming the folder and what differs).
std::optional<SequenceState> prepare_sequence_folder(const std::filesystem::path& folder,
                                                     const AnimationIdentity& identity,
                                                     const AnimationFrames& plan, int width_px,
                                                     int height_px, bool force,
                                                     std::string* problem);

// A stable 64-bit FNV-1a digest of `bytes`, as 16 hex digits.
std::string digest_hex(const std::string& bytes);

}  // namespace fr
