// explorer_setup.hpp — an explorer session as `explore` and `bench --explore` start it.
#pragma once

#include "app/explorer.hpp"
#include "cli/prepared_scene.hpp"

#include <memory>

namespace fr {

// An explorer session, as `explore` and `bench --explore` start it: settings (leniently: each
// problem is reported on `err` and in the overlay, and that value keeps its default), window size
// from --size or the settings, device, the scene library over the plugin folders, and the
// explorer on --scene with the command line's overrides.
struct ExplorerSetup {
  Settings settings;
  std::unique_ptr<RenderWorker> worker;  // renders for the explorer, on the chosen device
  std::unique_ptr<SceneLibrary> library;
  std::unique_ptr<Explorer> explorer;
  // Every preset in the plugin folders, and the files that failed to load as presets.
  std::vector<Preset> presets;
  std::vector<PresetProblem> preset_problems;
  bool scene_asked = false;  // --scene, --preset or --path was given
};
// A problem in the settings file or a --set (an unknown key, a bad value) is said as a warning,
// and the explorer opens with the rest; with `settings_problems_are_errors` (a measurement, as
// `bench --explore`) it is a usage error, as it is for `render` and `bench`.
// With `vet_in_background` (the window, which shows what is being prepared) the scenes not
// vetted before are vetted while it runs (app/scene_library.hpp); otherwise before it returns.
ExplorerSetup prepare_explorer(ParsedOptions options, bool settings_problems_are_errors = false,
                               bool vet_in_background = false);

}  // namespace fr
