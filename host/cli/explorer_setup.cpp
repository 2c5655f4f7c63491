#include "cli/explorer_setup.hpp"

#include "app/scene_library.hpp"
#include "io/log.hpp"

#include <spdlog/spdlog.h>

namespace fr {

ExplorerSetup prepare_explorer(ParsedOptions options, bool settings_problems_are_errors,
                               bool vet_in_background) {
  ExplorerSetup x;
  std::vector<SettingsProblem> problems;
  // (nullptr: load_settings throws the first problem as a usage error)
  x.settings = load_settings(options, settings_problems_are_errors ? nullptr : &problems);
  for (const auto& p : problems) spdlog::warn("{}", p.to_string());
  if (!options.has("size"))
    options.values["size"] = {std::to_string(x.settings.explorer.window_width_px) + "x" +
                              std::to_string(x.settings.explorer.window_height_px)};
  x.settings.render = render_settings_from(x.settings, options);
  const auto folders = plugin_folders(x.settings, options);
  if (folders.empty())
    throw std::runtime_error("no plugin folder found (build the plugins, or pass --plugins DIR)");
  // The scene asked for, checked against the plugins' descriptors (the scan cache: no kernel
  // built) before the library vets every scene's kernel, which on a first start takes a while.
  const std::optional<Preset> preset = preset_option(options, folders);
  if (preset) {
    apply_preset_settings(options, preset, x.settings);
    x.settings.render = render_settings_from(x.settings, options);
  }
  x.presets = load_presets(folders, &x.preset_problems);
  x.scene_asked = options.has("scene") || options.has("preset") || options.has("path");
  const std::string scene_id = scene_id_option(options, preset);
  {
    std::vector<std::string> available;
    bool found = false;
    for (const auto& o : load_plugins(folders, x.settings.plugins)) {
      if (!o.scene) continue;
      found = found || o.scene->info.id == scene_id;
      available.push_back(o.scene->info.id);
    }
    if (!found) throw unknown_scene(scene_id, available);
  }
  const DeviceInfo device = choose_device(x.settings, options);
  check_memory(x.settings.render, device, false);  // the window's size, at full resolution
  x.worker = std::make_unique<RenderWorker>(device, explorer_worker_limits(x.settings.plugins));
  std::vector<SceneEvent> events;
  x.library = std::make_unique<SceneLibrary>(folders, x.settings.plugins, x.settings.render,
                                             *x.worker, &events, vet_in_background);
  // The scenes found at start are listed at debug level (-v): the overlay lists them, and the
  // terminal says what fails and, later, what changes.
  for (const SceneEvent& e : events) {
    if (e.is_failure())
      log_scene_event(e);
    else
      spdlog::debug("{}", e.to_string());
  }
  if (x.library->find(scene_id) < 0) {
    std::vector<std::string> available;
    for (const auto& slot : x.library->slots()) available.push_back(slot.scene->info.id);
    throw unknown_scene(scene_id, available);
  }
  x.explorer = std::make_unique<Explorer>(x.settings, *x.worker, *x.library, scene_id);
  const SceneInfo& info = x.explorer->current().scene->info;
  apply_scene_overrides(info, options, x.explorer->current().state, preset);
  if (auto file = options.get("path")) {  // explore --path: play it from the start
    PathRecorder& recorder = x.explorer->path();
    recorder.scene_id = info.id;
    recorder.keyframes = load_path_option(info, *file).keyframes;
    std::string error;
    start_playback(recorder, info, &error);
  }
  return x;
}

}  // namespace fr
