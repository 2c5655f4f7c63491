// scene_instance.hpp — a scene in use: the host-owned state (parameter values, camera, lights,
// time, bounds) and the plugin's instance made by its create callback.
//
// The state is plain data the host can save, show and edit; the plugin sees it only during its
// update callback. Parameter values are clamped to their limits after every update, and the
// camera, lights and bounding radius it leaves are checked. An update that fails (an error, a
// crash, a hang, an invalid result) is not called again: the scene must be reloaded.
#pragma once

#include "plugin/scene_info.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fr {

// The state a scene starts with: its defaults.
SceneState make_default_state(const SceneInfo& info);

// Clamps every parameter value to its [min, max] (and ints/bools to whole numbers).
void clamp_params(const SceneInfo& info, std::vector<fr_value>& values);

class SceneInstance {
 public:
  // Calls the scene's create callback. On failure returns null and sets *error to the reason,
  // prefixed with the scene id.
  static std::unique_ptr<SceneInstance> create(std::shared_ptr<const LoadedScene> scene,
                                               std::string* error);
  ~SceneInstance();  // calls destroy
  SceneInstance(const SceneInstance&) = delete;
  SceneInstance& operator=(const SceneInstance&) = delete;

  // Runs the update callback at `time_s` on `state`. Returns false and sets *error (prefixed with
  // the scene id) if it fails, or failed before; `state` then keeps its values from before.
  bool update(SceneState& state, double time_s, std::string* error);

  const LoadedScene& scene() const { return *scene_; }
  bool failed() const { return !failure_.empty(); }

 private:
  explicit SceneInstance(std::shared_ptr<const LoadedScene> scene) : scene_(std::move(scene)) {}

  std::shared_ptr<const LoadedScene> scene_;  // pins the code that runs the callbacks
  uint64_t handle_ = 0;
  bool created_ = false;
  std::string failure_;  // the update failure; later updates return it without calling
};

}  // namespace fr
