// descriptor_copy.hpp — reading a plugin's entry symbol and descriptor into host memory.
//
// This is the only code that reads plugin memory. It checks each struct's size and reserved
// fields before reading past them, caps every count before reading the array it counts and every
// string before copying it, and then applies every rule of scene_checks.hpp to the copy.
#pragma once

#include "plugin/plugin_loader.hpp"

namespace fr {

struct DescriptorCopy {
  LoadResult result = LoadResult::InvalidScene;
  std::string message;  // why, when result != Loaded
  SceneInfo info;
  fr_create_fn create = nullptr;
  fr_destroy_fn destroy = nullptr;
  fr_update_fn update = nullptr;
};

// `entry` is the plugin's exported fractalis_scene_entry (or null when it has none).
DescriptorCopy copy_descriptor(const fr_scene_entry* entry);

}  // namespace fr
