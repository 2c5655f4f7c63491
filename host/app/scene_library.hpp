// scene_library.hpp — the scenes of a running explorer, kept in step with the plugin folders.
//
// New plugins are added; a changed plugin is loaded (in a scene-host process), its instance
// created and updated, its kernel built and a test render of it run in a child process
// (scene_vetting.hpp) beside the old one, and only when all of that worked does it replace the
// old one (parameter values carried over by key); otherwise the old one keeps running and the
// error is kept for the overlay. A file that declares the id of a scene another file provides is
// refused. A removed plugin keeps running until the user switches away from it.
#pragma once

#include "app/scene_slot.hpp"
#include "app/scene_vetting.hpp"
#include "plugin/plugin_policy.hpp"
#include "plugin/plugin_watcher.hpp"
#include "render/cl_runtime.hpp"
#include "render/render_settings.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fr {

class SceneLibrary {
 public:
  // Loads the folders (failures go to `messages`) and starts watching them.
  // Each scene is vetted (scene_vetting.hpp) before it is added, once per file content; the
  // test renders run in parallel.
  SceneLibrary(std::vector<std::filesystem::path> folders, const PluginPolicy& policy,
               const RenderSettings& settings, ClRuntime& runtime,
               std::vector<std::string>* messages);

  std::vector<SceneSlot>& slots() { return slots_; }
  int find(const std::string& id) const;  // slot index or -1

  // Applies the folder changes that became stable by now_s; returns one message per event
  // ("reloaded 'menger'", "kept the running 'menger': ...").
  std::vector<std::string> poll(double now_s, const RenderSettings& settings);

  // Drops a removed scene's slot (call when the user switches away from it).
  void drop_if_removed(int index);

 private:
  std::string add_or_replace(const std::filesystem::path& file, const RenderSettings& settings);

  PluginPolicy policy_;
  VettedScenes vetted_;
  ClRuntime& runtime_;
  std::vector<SceneSlot> slots_;
  std::vector<std::unique_ptr<PluginWatcher>> watchers_;
};

// A fresh slot for a loaded scene: default state, instance created and updated once. On failure
// returns false and sets *error.
bool make_slot(std::shared_ptr<const LoadedScene> scene, SceneSlot* slot, std::string* error);

}  // namespace fr
