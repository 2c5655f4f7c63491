#include "animate/frame_plan.hpp"

#include "io/atomic_file.hpp"
#include "io/echo.hpp"
#include "io/fnv1a.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace fr {

std::optional<AnimationFrames> plan_frames(double start_s, double end_s, int fps,
                                           std::string* problem) {
  const double steps = (end_s - start_s) * fps;
  // A hair of tolerance: a 2.1 s path at 10 fps is 21 steps, though 2.1 * 10 is 20.999...
  const double whole = std::floor(steps + 1e-9);
  if (!(whole + 1 <= kMaxAnimationFrames)) {
    *problem = "the path lasts " + std::to_string(end_s - start_s) + " s: at " +
               std::to_string(fps) + " fps that is more than " +
               std::to_string(kMaxAnimationFrames) + " frames";
    return std::nullopt;
  }
  AnimationFrames plan;
  plan.start_s = start_s;
  plan.fps = fps;
  plan.frames = static_cast<int>(whole) + 1;
  plan.ends_early = std::abs(steps - whole) > 1e-6;
  return plan;
}

std::string frame_file_name(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06d.png", frame);
  return name;
}

std::string digest_hex(const std::string& bytes) {
  return hex16(fnv1a(bytes));
}

namespace {

std::string identity_text(const AnimationIdentity& identity) {
  std::string text = "# What this folder's frames are; `fractalis animate` resumes only these.\n";
  for (const auto& [key, value] : identity) text += key + " = " + value + "\n";
  return text;
}

// The identity a record file holds, or nullopt when it is not one.
std::optional<AnimationIdentity> read_identity(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  AnimationIdentity identity;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) return std::nullopt;
    identity.emplace_back(line.substr(0, eq), line.substr(eq + 3));
  }
  return identity;
}

bool is_frame_name(const std::string& name) {
  if (name.size() != 16 || name.rfind("frame_", 0) != 0 || name.substr(12) != ".png") return false;
  for (int i = 6; i < 12; ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

// A PNG that starts with an IHDR of this size and ends with IEND: a frame that was written whole.
bool whole_png_of_size(const std::filesystem::path& file, int width_px, int height_px) {
  std::ifstream in(file, std::ios::binary);
  unsigned char head[24];
  if (!in.read(reinterpret_cast<char*>(head), sizeof head)) return false;
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (std::memcmp(head, signature, 8) != 0 || std::memcmp(head + 12, "IHDR", 4) != 0) return false;
  auto be32 = [](const unsigned char* p) {
    return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | p[3];
  };
  if (be32(head + 16) != uint32_t(width_px) || be32(head + 20) != uint32_t(height_px)) return false;
  unsigned char tail[8];
  if (!in.seekg(-8, std::ios::end) || !in.read(reinterpret_cast<char*>(tail), sizeof tail))
    return false;
  return std::memcmp(tail, "IEND", 4) == 0;
}

}  // namespace

std::optional<SequenceState> prepare_sequence_folder(const std::filesystem::path& folder,
                                                     const AnimationIdentity& identity,
                                                     const AnimationFrames& plan, int width_px,
                                                     int height_px, bool force,
                                                     std::string* problem) {
  namespace fs = std::filesystem;
  std::string named(1, '\'');
  named += echo(folder.string());
  named += '\'';
  std::error_code ec;
  const auto status = fs::status(folder, ec);
  if (status.type() == fs::file_type::not_found) {
    if (!fs::create_directory(folder, ec)) {
      *problem = "cannot create the folder " + named + ": " + ec.message();
      return std::nullopt;
    }
  } else if (status.type() != fs::file_type::directory) {
    *problem = named + " is not a folder (a video needs an extension: .mp4, .mkv or .webm)";
    return std::nullopt;
  }
  const fs::path record = folder / kSequenceRecordName;
  std::vector<fs::path> frames;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (is_frame_name(entry.path().filename().string())) frames.push_back(entry.path());
  if (ec) {
    *problem = "cannot read the folder " + named + ": " + ec.message();
    return std::nullopt;
  }
  if (force) {
    for (const auto& f : frames) fs::remove(f, ec);
    frames.clear();
  } else if (fs::exists(record)) {
    const auto recorded = read_identity(record);
    if (!recorded) {
      *problem = named + " has a damaged " + kSequenceRecordName + "; --force renders it anew";
      return std::nullopt;
    }
    for (const auto& [key, value] : identity) {
      std::string was = "(none)";
      for (const auto& [k, v] : *recorded)
        if (k == key) was = v;
      if (was != value) {
        *problem = named + " holds frames of another animation (its " + key + " was " + was +
                   ", now " + value + "); --force renders it anew";
        return std::nullopt;
      }
    }
  } else if (!frames.empty()) {
    *problem = named + " holds frames that fractalis did not record; --force replaces them";
    return std::nullopt;
  }
  std::string error;
  if (!write_file_atomic(record, identity_text(identity), &error)) {
    *problem = error;
    return std::nullopt;
  }
  SequenceState state;
  state.frame_done.assign(plan.frames, false);
  for (int i = 0; i < plan.frames; ++i)
    if (whole_png_of_size(folder / frame_file_name(i), width_px, height_px)) {
      state.frame_done[i] = true;
      ++state.done;
    }
  return state;
}

}  // namespace fr
