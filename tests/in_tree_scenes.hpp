// in_tree_scenes.hpp — the in-tree scenes' ids, for tests that hold for every scene.
#pragma once

#include "test_paths.hpp"

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

// The scenes the per-scene tests (check_test, scenes_render_test) run here: every one, except
// where each run costs far more than on a plain Linux build and what could break there is the
// host's own code, which any scene exercises as well as forty do:
// - the Windows build's tests under Wine (scripts/test-windows.sh), where each `fractalis check`
//   costs about 20 s of process start-up;
// - the sanitizer build in CI (.ci/run sets FRACTALIS_TEST_SCENES=sample), where the plain build
//   has just checked every scene.
// Then one scene of each family runs, with the benchmark and the hybrid (ABI 1.2's choice type).
// FRACTALIS_TEST_SCENES=all runs every scene in either.
inline std::vector<std::string> scene_ids_for_this_platform() {
  std::vector<std::string> ids = in_tree_scene_ids();
  const char* chosen = std::getenv("FRACTALIS_TEST_SCENES");
  const std::string choice = chosen ? chosen : "";
#ifdef _WIN32
  const bool sample = choice != "all";
#else
  const bool sample = choice == "sample";
#endif
  if (sample) {
    const std::vector<std::string> kept_ids = {
        "benchmark", "hybrid",   "julia",      "kalibox", "kifs_octahedron", "kleinian",
        "mandelbox", "mandelbulb", "menger", "menger_temple", "sierpinski",  "tetrabrot"};
    std::vector<std::string> kept;
    for (const std::string& id : ids)
      if (std::find(kept_ids.begin(), kept_ids.end(), id) != kept_ids.end()) kept.push_back(id);
    ids = kept;
  }
  return ids;
}

}  // namespace fr::test
