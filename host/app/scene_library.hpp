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
#include "app/vet_queue.hpp"
#include "render/scene_vetting.hpp"
#include "plugin/plugin_policy.hpp"
#include "plugin/plugin_watcher.hpp"
#include "worker/render_worker.hpp"
#include "render/render_settings.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fr {

// What happened to a scene file, as the explorer logs it and reacts to it.
struct SceneEvent {
  enum class Kind {
    Added,     // a new scene, at start or dropped into a folder
    Reloaded,  // a changed file replaced its running scene
    Kept,      // a changed file failed; the running scene stays (reason says why)
    Skipped,   // a file that gave no scene (reason says why)
    Removed,   // the file went; the scene runs until the user switches away
  };
  Kind kind = Kind::Added;
  std::string scene_id;  // empty for Skipped
  std::filesystem::path file;
  std::string reason;  // Kept and Skipped
  // One line: "reloaded 'menger' from menger.so", "skipped bad.so: not an ELF file".
  std::string to_string() const;
  bool is_failure() const { return kind == Kind::Kept || kind == Kind::Skipped; }
};

// Logs the event through the one channel (io/log.hpp): failures as warnings, the rest as info.
void log_scene_event(const SceneEvent& event);

class SceneLibrary {
 public:
  // Loads the folders (an event per file goes to `events`) and starts watching them.
  // Each scene is vetted (scene_vetting.hpp) once per file content before anything renders it;
  // the test renders run in parallel. Without `vet_in_background` the constructor waits for them
  // and leaves out the scenes that fail (Skipped events). With it (the explorer's window) it
  // returns at once: the scenes not vetted before are slots that are `preparing` until poll()
  // takes their results in (a scene that fails stays as a `refused` slot, its error said by a
  // Skipped event), and prioritize() says which one the user waits for.
  SceneLibrary(std::vector<std::filesystem::path> folders, const PluginPolicy& policy,
               const RenderSettings& settings, RenderWorker& worker,
               std::vector<SceneEvent>* events, bool vet_in_background = false);

  std::vector<SceneSlot>& slots() { return slots_; }
  const std::vector<SceneSlot>& slots() const { return slots_; }
  int find(const std::string& id) const;  // slot index or -1

  // The slot's test render first, when it is still waiting for one.
  void prioritize(int index);
  // Slots still waiting for their test render.
  int preparing() const;

  // Applies the folder changes that became stable by now_s; returns what happened, in order.
  std::vector<SceneEvent> poll(double now_s, const RenderSettings& settings);

  // The files in the folders that give no scene now (each a Skipped event: the file and why),
  // for the scene browser. A file that loads later leaves the list; one removed leaves it too.
  const std::vector<SceneEvent>& failed_files() const { return failed_files_; }
  // Counts the changes: a poll that added, reloaded, kept, skipped or removed anything (or a
  // dropped slot) makes it one larger, so a view of the library knows when to look again.
  uint64_t generation() const { return generation_; }

  // Drops a removed scene's slot (call when the user switches away from it).
  void drop_if_removed(int index);

 private:
  SceneEvent add_or_replace(const std::filesystem::path& file, const RenderSettings& settings);
  // Takes in the background test renders that finished; returns a Skipped event per failure.
  std::vector<SceneEvent> take_vet_results();

  PluginPolicy policy_;
  RenderSettings vet_settings_;  // the settings the background test renders run with
  VettedScenes vetted_;
  std::unique_ptr<VetQueue> vet_queue_;  // while a background vetting is under way
  RenderWorker& worker_;
  std::vector<SceneSlot> slots_;
  std::vector<SceneEvent> failed_files_;
  uint64_t generation_ = 0;
  std::vector<std::unique_ptr<PluginWatcher>> watchers_;
};

// A fresh slot for a loaded scene: default state, instance created and updated once. On failure
// returns false and sets *error.
bool make_slot(std::shared_ptr<const LoadedScene> scene, SceneSlot* slot, std::string* error);

}  // namespace fr
