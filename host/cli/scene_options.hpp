// scene_options.hpp — from command-line options to what commands share: settings, plugin
// folders, choosing the scene and device, and applying command-line overrides. Bad input becomes
// a UsageError.
#pragma once

#include "cli/options.hpp"
#include "path/camera_path.hpp"
#include "path/preset.hpp"
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
// --config FILE, as every command that reads settings takes it.
OptionSpec config_option_spec();

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
// A folder fractalis ships: `in_source_tree` when it runs from the build tree, else
// `installed` (relative to the install prefix, found from the executable).
std::filesystem::path shipped_folder(const std::filesystem::path& in_source_tree,
                                     const std::filesystem::path& installed);

// Where a user drops scenes: $XDG_DATA_HOME/fractalis/scenes (~/.local/share/fractalis/scenes).
std::filesystem::path user_scene_folder();

// Loads the folders, logs a warning for each plugin that failed, and returns the outcomes.
std::vector<LoadOutcome> load_plugins(const std::vector<std::filesystem::path>& folders,
                                      const PluginPolicy& policy);

// "unknown scene 'ID' (available: a, b)", the id echoed safely.
UsageError unknown_scene(const std::string& id, const std::vector<std::string>& available);

// The loaded scene with this id, or a UsageError listing the ids there are.
std::shared_ptr<const LoadedScene> find_scene(const std::vector<LoadOutcome>& outcomes,
                                              const std::string& id);

// --preset NAME, found in the plugin folders' presets/ (nullopt without --preset), or --preset
// FILE: a preset file (.toml) or a Mandelbulber2 settings file (.fract) imported on the fly
// (cli/preset_files.hpp). A UsageError names an unknown preset (with the ones there are), a file
// with a problem, or every reason a .fract file cannot be imported.
std::optional<Preset> preset_option(const ParsedOptions& options,
                                    const std::vector<std::filesystem::path>& folders);
// The preset's [settings] over `settings`, then --set again (the command line wins). A setting
// the preset gets wrong is a UsageError naming the preset's file.
void apply_preset_settings(const ParsedOptions& options, const std::optional<Preset>& preset,
                           Settings& settings);
// The scene to use: --scene, else the preset's, else mandelbulb; a --scene that differs from the
// preset's scene is a UsageError.
std::string scene_id_option(const ParsedOptions& options, const std::optional<Preset>& preset);
// Applies the preset (its values and view, if any), then --param key=value (repeatable) and
// --eye/--target/--fov, to `state`.
void apply_scene_overrides(const SceneInfo& info, const ParsedOptions& options, SceneState& state,
                           const std::optional<Preset>& preset = std::nullopt);

// --size, --lanes, --precision over the settings' render defaults.
RenderSettings render_settings_from(const Settings& settings, const ParsedOptions& options,
                                    int max_side = kMaxImageSide);

// The device: --device, else settings' device.select, else the default rule.
DeviceInfo choose_device(const Settings& settings, const ParsedOptions& options);

}  // namespace fr
