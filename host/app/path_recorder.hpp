// path_recorder.hpp — the explorer's camera path: keyframes recorded from the view on screen,
// saved and loaded as path files (path/camera_path.hpp, the files `render --path` and `animate`
// read), and played back in the window.
#pragma once

#include "path/camera_path.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace fr {

struct PathRecorder {
  std::string scene_id;  // the scene the keyframes were recorded in (their parameters are its)
  std::vector<Keyframe> keyframes;
  double spacing_s = 2;  // time from one recorded keyframe to the next
  bool playing = false;
  double play_s = 0;  // time since the path's first keyframe, while playing
};

// Appends the view and parameters of `state` as the next keyframe, spacing_s after the last one.
// Keyframes of another scene are dropped first: a path belongs to one scene.
void add_keyframe(PathRecorder& recorder, const SceneInfo& scene, const SceneState& state);
void remove_last_keyframe(PathRecorder& recorder);

// The recorded keyframes as a path (at least two), or nullopt with *error saying why not.
std::optional<CameraPath> recorded_path(const PathRecorder& recorder, const SceneInfo& scene,
                                        std::string* error);

// Writes the recorded path to `file` (atomically), or says why not.
bool save_recorded_path(const PathRecorder& recorder, const SceneInfo& scene,
                        const std::filesystem::path& file, std::string* error);
// Replaces the keyframes with those of `file`, read for `scene`; on failure *error is the file's
// first FILE:LINE problem and the keyframes stay as they were.
bool load_recorded_path(PathRecorder& recorder, const SceneInfo& scene,
                        const std::filesystem::path& file, std::string* error);

// Playback from the path's start; false with *error when there is no path to play.
bool start_playback(PathRecorder& recorder, const SceneInfo& scene, std::string* error);
// Starts playback, or stops it while playing; a path that cannot play is logged as a warning.
void toggle_playback(PathRecorder& recorder, const SceneInfo& scene);
// Moves playback on by dt_s and puts the camera and parameters at that time into `state`;
// playback stops after the last keyframe (which is shown). Does nothing when not playing.
void advance_playback(PathRecorder& recorder, const SceneInfo& scene, double dt_s,
                      SceneState& state);

}  // namespace fr
