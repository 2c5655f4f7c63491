// scene_slot.hpp — a scene as the explorer holds it: the loaded plugin, its instance and the
// host-owned state, which stays with the scene for the whole session (switching away and back
// keeps parameters and camera; a reload keeps parameters by key).
#pragma once

#include "plugin/scene_instance.hpp"

#include <memory>
#include <string>

namespace fr {

struct SceneSlot {
  std::shared_ptr<const LoadedScene> scene;
  std::unique_ptr<SceneInstance> instance;
  SceneState state;
  std::string error;     // the last problem (a failed reload or update), shown in the overlay
  bool removed = false;  // its file left the folder; it runs until the user switches away
  // Its test render (render/scene_vetting.hpp) has not finished yet: nothing renders or probes
  // it. Only while a library vets in the background (a first start).
  bool preparing = false;
  // Its test render failed (`error` says why): nothing renders or probes it until its file
  // changes and the new one passes.
  bool refused = false;
  bool usable() const { return !preparing && !refused; }
};

// Carries parameter values from `old_info` to `new_info` by key: keys that went are dropped,
// new keys take their defaults, and values out of the new ranges are clamped.
std::vector<fr_value> rebind_params(const SceneInfo& old_info,
                                    const std::vector<fr_value>& old_values,
                                    const SceneInfo& new_info);

}  // namespace fr
