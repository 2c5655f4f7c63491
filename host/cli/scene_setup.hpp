// scene_setup.hpp — what `render`, `bench` and `list` share: settings, plugin folders, choosing
// the scene and device, and applying command-line overrides. Bad input becomes a UsageError.
#pragma once

#include "app/explorer.hpp"
#include "cli/options.hpp"
#include "path/camera_path.hpp"
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_instance.hpp"
#include "render/device.hpp"
#include "settings/settings.hpp"

#include <iosfwd>
#include <memory>
#include <vector>

namespace fr {

// Options shared by commands that render: scene, view, parameters, kernel shape, device.
std::vector<OptionSpec> scene_option_specs();
// Options shared by every command that loads plugins: --plugins, --config.
std::vector<OptionSpec> plugin_option_specs();

// Defaults, then the settings file (--config FILE, else the user's file), then the options.
// Without `problems`, the first problem is a UsageError; with it, problems are collected there and
// each wrong value keeps its default (the explorer starts anyway and shows them).
Settings load_settings(const ParsedOptions& options,
                       std::vector<SettingsProblem>* problems = nullptr);

// --plugins DIR (only that folder), else plugins.folders from settings (only those), else the
// scenes built with this executable (the build tree's, or the installed ones) and then the
// user's folder (user_scene_folder), each when it exists.
std::vector<std::filesystem::path> plugin_folders(const Settings& settings,
                                                  const ParsedOptions& options);

// A camera path that ships with fractalis (config/paths/ in the source tree, share/fractalis/paths
// installed), for the executable that runs: "benchmark.toml" is the benchmark scene's route.
std::filesystem::path shipped_path_file(const std::string& name);

// Where a user drops scenes: $XDG_DATA_HOME/fractalis/scenes (~/.local/share/fractalis/scenes).
std::filesystem::path user_scene_folder();

// Loads the folders, logs a warning for each plugin that failed, and returns the outcomes.
std::vector<LoadOutcome> load_plugins(const std::vector<std::filesystem::path>& folders,
                                      const PluginPolicy& policy);

// The loaded scene with this id, or a UsageError listing the ids there are.
std::shared_ptr<const LoadedScene> find_scene(const std::vector<LoadOutcome>& outcomes,
                                              const std::string& id);

// Applies --param key=value (repeatable) and --eye/--target/--fov to `state`.
void apply_scene_overrides(const SceneInfo& info, const ParsedOptions& options, SceneState& state);

// --size, --lanes, --precision over the settings' render defaults.
RenderSettings render_settings_from(const Settings& settings, const ParsedOptions& options,
                                    int max_side = kMaxImageSide);

// The device: --device, else settings' device.select, else the default rule.
DeviceInfo choose_device(const Settings& settings, const ParsedOptions& options);

}  // namespace fr

namespace fr {

// Everything a rendering command needs, set up from its options.
struct PreparedScene {
  Settings settings;
  std::shared_ptr<const LoadedScene> scene;
  std::unique_ptr<SceneInstance> instance;
  SceneState state;
  RenderSettings render;
  DeviceInfo device;
};

// Settings, plugins (failures logged as warnings), scene (--scene, default mandelbulb), overrides,
// device, and the scene's instance. Throws UsageError for bad input, runtime_error when the
// scene's create callback fails.
PreparedScene prepare_scene(const ParsedOptions& options, int max_side = kMaxImageSide);

// The camera path `file` for scene `info`, or a UsageError "--path: FILE:LINE: problem".
CameraPath load_path_option(const SceneInfo& info, const std::string& file);

// Sets `state`'s camera and parameters from the camera path `file` (path/camera_path.hpp) at
// the state's time, or at the path's start without --time. Throws a UsageError with the file's
// FILE:LINE problem.
void apply_camera_path(const SceneInfo& info, const std::string& file, const ParsedOptions& options,
                       SceneState& state);

// Throws a UsageError naming the limit when an image of the settings' size cannot be rendered on
// `device` in this process (render/memory_budget.hpp); `all_passes`: every pass is read back.
void check_memory(const RenderSettings& render, const DeviceInfo& device, bool all_passes);

}  // namespace fr

namespace fr {

// An explorer session, as `explore` and `bench --explore` start it: settings (leniently: each
// problem is reported on `err` and in the overlay, and that value keeps its default), window size
// from --size or the settings, device, the scene library over the plugin folders, and the
// explorer on --scene with the command line's overrides.
struct ExplorerSetup {
  Settings settings;
  std::unique_ptr<ClRuntime> runtime;
  std::unique_ptr<SceneLibrary> library;
  std::unique_ptr<Explorer> explorer;
};
ExplorerSetup prepare_explorer(ParsedOptions options);

}  // namespace fr
