// in_tree_scenes.hpp — the in-tree scenes' ids, for tests that hold for every scene.
#pragma once

#include <algorithm>
#include <cstdlib>
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

// The scenes the per-scene tests (check_test, scenes_render_test) run here. On Linux every one.
// The Windows build's tests run under Wine (scripts/test-windows.sh), where each `fractalis check`
// costs about 20 s of process start-up; there one scene of each family runs, with the benchmark
// and the hybrid (the ABI 1.2 choice type): what a Windows build can break is the platform layer,
// which each of them exercises, and the Linux suite checks every scene's own code.
// FRACTALIS_TEST_EVERY_SCENE=1 runs them all there too.
inline std::vector<std::string> scene_ids_for_this_platform() {
  std::vector<std::string> ids = in_tree_scene_ids();
#ifdef _WIN32
  const char* every = std::getenv("FRACTALIS_TEST_EVERY_SCENE");
  if (!every || std::string(every) != "1") {
    const std::vector<std::string> sample = {
        "benchmark", "hybrid",   "julia",    "kalibox",       "kifs_octahedron", "kleinian",
        "mandelbox", "mandelbulb", "menger", "menger_temple", "sierpinski",      "tetrabrot"};
    std::vector<std::string> kept;
    for (const std::string& id : ids)
      if (std::find(sample.begin(), sample.end(), id) != sample.end()) kept.push_back(id);
    ids = kept;
  }
#endif
  return ids;
}

}  // namespace fr::test
