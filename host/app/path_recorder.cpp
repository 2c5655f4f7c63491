#include "app/path_recorder.hpp"

#include "io/atomic_file.hpp"
#include "scene/vec3.hpp"

#include <spdlog/spdlog.h>

namespace fr {

void add_keyframe(PathRecorder& recorder, const SceneInfo& scene, const SceneState& state) {
  if (recorder.scene_id != scene.id) {
    recorder.keyframes.clear();
    recorder.playing = false;
    recorder.scene_id = scene.id;
  }
  Keyframe k;
  k.time_s =
      recorder.keyframes.empty() ? 0.0 : recorder.keyframes.back().time_s + recorder.spacing_s;
  k.eye = to_dvec3(state.camera.eye);
  k.target = to_dvec3(state.camera.target);
  k.eye_lo = to_dvec3(state.camera_lo.eye);
  k.target_lo = to_dvec3(state.camera_lo.target);
  k.up = to_dvec3(state.camera.up);
  k.fov_deg = state.camera.fov_deg;
  k.params = state.params;
  recorder.keyframes.push_back(std::move(k));
}

void remove_last_keyframe(PathRecorder& recorder) {
  if (!recorder.keyframes.empty()) recorder.keyframes.pop_back();
  if (recorder.keyframes.size() < 2) recorder.playing = false;
}

std::optional<CameraPath> recorded_path(const PathRecorder& recorder, const SceneInfo& scene,
                                        std::string* error) {
  if (recorder.scene_id != scene.id || recorder.keyframes.size() < 2) {
    const size_t have = recorder.scene_id == scene.id ? recorder.keyframes.size() : 0;
    *error = "a path needs at least two keyframes of scene '" + scene.id + "' (it has " +
             std::to_string(have) + "); add them with the keyframe key";
    return std::nullopt;
  }
  CameraPath path;
  path.file = "(recorded)";
  path.keyframes = recorder.keyframes;
  return path;
}

bool save_recorded_path(const PathRecorder& recorder, const SceneInfo& scene,
                        const std::filesystem::path& file, std::string* error) {
  const auto path = recorded_path(recorder, scene, error);
  return path && write_file_atomic(file, format_camera_path(*path, scene), error);
}

bool load_recorded_path(PathRecorder& recorder, const SceneInfo& scene,
                        const std::filesystem::path& file, std::string* error) {
  std::vector<PathProblem> problems;
  const auto path = load_camera_path(file, scene, &problems);
  if (!path) {
    *error = problems.empty() ? "cannot read " + file.string() : problems.front().to_string();
    return false;
  }
  recorder.scene_id = scene.id;
  recorder.keyframes = path->keyframes;
  recorder.playing = false;
  // The spacing of what is recorded next follows the file's last interval.
  const size_t n = recorder.keyframes.size();
  recorder.spacing_s = recorder.keyframes[n - 1].time_s - recorder.keyframes[n - 2].time_s;
  return true;
}

bool start_playback(PathRecorder& recorder, const SceneInfo& scene, std::string* error) {
  if (!recorded_path(recorder, scene, error)) return false;
  recorder.playing = true;
  recorder.play_s = 0;
  return true;
}

void toggle_playback(PathRecorder& recorder, const SceneInfo& scene) {
  std::string error;
  if (recorder.playing)
    recorder.playing = false;
  else if (!start_playback(recorder, scene, &error))
    spdlog::warn("cannot play the path: {}", error);
}

void advance_playback(PathRecorder& recorder, const SceneInfo& scene, double dt_s,
                      SceneState& state) {
  if (!recorder.playing) return;
  std::string error;
  const auto path = recorded_path(recorder, scene, &error);
  if (!path) {
    recorder.playing = false;
    return;
  }
  const double duration_s = path->end_s() - path->start_s();
  const PathSample sample =
      sample_camera_path(*path, scene, path->start_s() + std::min(recorder.play_s, duration_s));
  state.camera = sample.camera;
  state.camera_lo = sample.camera_lo;
  state.params = sample.params;
  if (recorder.play_s >= duration_s) recorder.playing = false;  // the last keyframe was shown
  recorder.play_s += dt_s;
}

}  // namespace fr
