// plugin_loader.hpp — turning a plugin file into a LoadedScene, and a folder into a scene list.
//
// By default no plugin code runs in the host: each file is loaded in a scene-host process
// (scene_host_process.hpp), which checks the entry symbol's ABI version and struct sizes before
// anything else, copies the descriptor and sends it back; the host checks that copy again. A
// plugin that fails is reported with its file, the reason and what was expected, and skipped.
#pragma once

#include "plugin/plugin_policy.hpp"
#include "plugin/scene_info.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fr {

enum class LoadResult : uint32_t {
  Loaded,          // usable; LoadOutcome::scene is set
  NotLoadable,     // not an ELF shared library, truncated, or dlopen failed: rebuild the plugin
  NoEntrySymbol,   // no `fractalis_scene_entry`: not built with the SDK's FR_SCENE_ENTRY
  WrongAbiMajor,   // built for another ABI major: rebuild against this host's SDK
  AbiTooNew,       // needs a newer host minor than this one: update the host
  StructTooSmall,  // a struct is smaller than ABI 1.0 defines: corrupt or hand-made entry
  InvalidScene,    // a field breaks a rule (null, too long, not clean text, out of range): fix it
  DuplicateId,     // another plugin already provides this scene id: remove one of them
  Refused,         // not a regular file, or writable by other users: see the message
  Crashed,         // its code crashed, hung or aborted while loading: fix its constructors
};

const char* load_result_name(LoadResult result);

struct LoadOutcome {
  LoadResult result = LoadResult::NotLoadable;
  std::filesystem::path file;
  std::string message;  // one line: what was wrong and what was expected; empty when Loaded
  std::shared_ptr<const LoadedScene> scene;
};

// Loads one plugin file and checks it. Never throws, crashes or hangs for a bad plugin.
LoadOutcome load_scene_plugin(const std::filesystem::path& file, const PluginPolicy& policy = {});

// Loads every *.so in the folders, in order (files sorted by name within a folder); entries that
// are not regular files are reported as Refused with their reason. A scene id seen before is
// refused as DuplicateId, naming the file that has it.
std::vector<LoadOutcome> load_scene_folder(const std::vector<std::filesystem::path>& folders,
                                           const PluginPolicy& policy = {});

}  // namespace fr
