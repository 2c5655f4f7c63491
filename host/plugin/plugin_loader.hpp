// plugin_loader.hpp — turning a plugin file into a LoadedScene, and a folder into a scene list.
//
// Every check runs on the plugin's static data before any of its code is called: the entry
// symbol's ABI version and struct size first, then the descriptor's required fields. A plugin
// that fails is reported with its file, the reason and what was expected, and skipped.
#pragma once

#include "plugin/scene_info.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fr {

enum class LoadResult {
  Loaded,          // usable; LoadOutcome::scene is set
  NotLoadable,     // not an ELF shared library, truncated, or dlopen failed: rebuild the plugin
  NoEntrySymbol,   // no `fractalis_scene_entry`: not built with the SDK's FR_SCENE_ENTRY
  WrongAbiMajor,   // built for another ABI major: rebuild against this host's SDK
  AbiTooNew,       // needs a newer host minor than this one: update the host
  StructTooSmall,  // a struct is smaller than ABI 1.0 defines: corrupt or hand-made entry
  InvalidScene,    // a required field is null or a value is out of its domain: fix the scene
  DuplicateId,     // another plugin already provides this scene id: remove one of them
};

const char* load_result_name(LoadResult result);

struct LoadOutcome {
  LoadResult result = LoadResult::NotLoadable;
  std::filesystem::path file;
  std::string message;  // one line: what was wrong and what was expected; empty when Loaded
  std::shared_ptr<const LoadedScene> scene;
};

// Loads one plugin file (from a private copy) and validates it. Never throws for a bad plugin.
LoadOutcome load_scene_plugin(const std::filesystem::path& file);

// Loads every *.so in the folders, in order (files sorted by name within a folder). A scene id
// seen before is refused as DuplicateId, naming the file that has it.
std::vector<LoadOutcome> load_scene_folder(const std::vector<std::filesystem::path>& folders);

}  // namespace fr
