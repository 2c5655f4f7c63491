// in_tree_scenes.hpp — the in-tree scenes' ids, for tests that hold for every scene.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace fr::test {

// The in-tree scenes: the ids of the plugins the build put into its scene folder (each file is
// named after its scene's id), sorted. Tests that hold for every scene iterate this, so a scene
// added under plugins/ is tested without a list to update.
inline std::vector<std::string> in_tree_scene_ids() {
  std::vector<std::string> ids;
  for (const auto& entry : std::filesystem::directory_iterator(SCENE_PLUGIN_DIR))
    if (entry.path().extension() == PLUGIN_SUFFIX) ids.push_back(entry.path().stem().string());
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace fr::test
