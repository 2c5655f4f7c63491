// descriptor_copy.hpp — reading a plugin's entry symbol and descriptor into host memory.
//
// This is the only code that reads plugin memory. It checks each struct's size and reserved
// fields before reading past them, caps every count before reading the array it counts and every
// string before copying it, and then applies every rule of scene_checks.hpp to the copy.
#pragma once

#include "plugin/plugin_loader.hpp"

#include <functional>

namespace fr {

struct DescriptorCopy {
  LoadResult result = LoadResult::InvalidScene;
  std::string message;  // why, when result != Loaded
  SceneInfo info;
  fr_create_fn create = nullptr;
  fr_destroy_fn destroy = nullptr;
  fr_update_fn update = nullptr;
  void (*deinit)(void) = nullptr;  // ABI 1.1: to call before the library is unloaded
};

// `entry` is the plugin's exported fractalis_scene_entry (or null when it has none). `init`, when
// given, runs after the entry's version and size checks and before the descriptor is read (the
// ABI 1.1 init call); a non-empty result is the reason the plugin is refused.
// The ABI 1.1 init call as copy_descriptor's `init` wants it: "" when it worked (or there is
// none), else "init failed: <the plugin's reason>".
std::string init_error(const fr_scene_entry& entry, const std::string& plugin_path);

DescriptorCopy copy_descriptor(
    const fr_scene_entry* entry,
    const std::function<std::string(const fr_scene_entry&)>& init = nullptr);

}  // namespace fr
