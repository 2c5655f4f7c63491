// scene_instance.hpp — a scene in use: the host-owned state (parameter values, camera, lights,
// time, bounds) and the plugin's instance made by its create callback.
//
// The state is plain data the host can save, show and edit; the plugin sees it only during its
// update callback. Parameter values are clamped to their limits after every update.
#pragma once

#include "plugin/scene_info.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fr {

struct SceneState {
  std::vector<fr_value> params;  // one per SceneInfo::params, same order
  fr_camera camera{};
  std::vector<fr_light> lights;
  double time_s = 0;
  double dt_s = 0;
  uint64_t frame_index = 0;
  double bounding_radius = 0;
};

// The state a scene starts with: its defaults.
SceneState make_default_state(const SceneInfo& info);

// Clamps every parameter value to its [min, max] (and ints/bools to whole numbers).
void clamp_params(const SceneInfo& info, std::vector<fr_value>& values);

class SceneInstance {
 public:
  // Calls the scene's create callback. On failure returns null and sets *error to the plugin's
  // logged reason.
  static std::unique_ptr<SceneInstance> create(std::shared_ptr<const LoadedScene> scene,
                                               std::string* error);
  ~SceneInstance();  // calls destroy
  SceneInstance(const SceneInstance&) = delete;
  SceneInstance& operator=(const SceneInstance&) = delete;

  // Runs the update callback at `time_s` on `state`. Returns false and sets *error (the plugin's
  // logged reason, prefixed with the scene id) if it reports an error.
  bool update(SceneState& state, double time_s, std::string* error);

  const LoadedScene& scene() const { return *scene_; }

 private:
  SceneInstance(std::shared_ptr<const LoadedScene> scene) : scene_(std::move(scene)) {}
  static void log_from_plugin(void* host_data, fr_log_level level, const char* message);
  fr_host host_api();

  std::shared_ptr<const LoadedScene> scene_;  // pins the library
  void* instance_ = nullptr;
  bool created_ = false;
  std::string last_error_;  // the last FR_LOG_ERROR message the plugin logged
};

}  // namespace fr
