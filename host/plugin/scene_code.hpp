// scene_code.hpp — what runs a scene's create, update and destroy callbacks.
//
// Two kinds: InProcessCode calls the plugin's functions directly (used inside a scene-host
// process, and in the host only with plugins.isolation = "none"); IsolatedCode
// (scene_host_process.hpp) forwards each call to a scene-host process with a time limit. Either
// way a call ends in a CallOutcome — a crash, hang or exception is an outcome, not the host's end.
#pragma once

#include "plugin/scene_info.hpp"
#include "plugin/scene_wire.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fr {

class PluginLibrary;

struct CallOutcome {
  bool ok = false;
  // When !ok, why: "update failed: <the reason the plugin logged>", "threw a C++ exception: ...",
  // "the scene host crashed (SIGSEGV)", "did not return within 2 s".
  std::string error;
  std::vector<PluginMessage> messages;  // what the plugin logged during the call
};

class SceneCode {
 public:
  virtual ~SceneCode() = default;
  // Makes one instance of the scene; `*instance` is its handle for the other calls.
  virtual CallOutcome create(uint64_t* instance) = 0;
  // Runs the update callback on `state` (a no-op when the scene has none).
  virtual CallOutcome update(uint64_t instance, SceneState& state) = 0;
  // Destroys an instance; failures are logged, not returned (there is nothing left to do).
  virtual void destroy(uint64_t instance) = 0;
  // For `fractalis check`: the scene-host process's heap, threads and plugin mappings, now or
  // (unload) after every instance is destroyed and the library closed. Null where there is no
  // such process to ask (in-process code, or a scene without callbacks).
  virtual std::optional<HostStats> host_stats(bool unload, std::string* error) {
    (void)unload;
    (void)error;
    return std::nullopt;
  }
};

// Calls an ABI 1.1 entry's init (if it has one) with the plugin's path as the user named it.
CallOutcome run_entry_init(const fr_scene_entry& entry, const std::string& plugin_path);

// The plugin's callbacks, called in this process. Every call catches everything the plugin throws.
class InProcessCode final : public SceneCode {
 public:
  InProcessCode(std::shared_ptr<PluginLibrary> library, fr_create_fn create, fr_destroy_fn destroy,
                fr_update_fn update)
      : library_(std::move(library)), create_(create), destroy_(destroy), update_(update) {}
  ~InProcessCode() override;

  CallOutcome create(uint64_t* instance) override;
  CallOutcome update(uint64_t instance, SceneState& state) override;
  void destroy(uint64_t instance) override;
  // Destroys every instance (the library itself is closed by whoever holds the last reference).
  void destroy_all();

 private:
  std::shared_ptr<PluginLibrary> library_;  // keeps the callbacks mapped
  fr_create_fn create_;
  fr_destroy_fn destroy_;
  fr_update_fn update_;
  std::map<uint64_t, void*> instances_;
  uint64_t next_handle_ = 1;
};

}  // namespace fr
