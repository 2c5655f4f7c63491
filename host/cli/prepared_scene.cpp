#include "cli/prepared_scene.hpp"

#include "cli/watchdog.hpp"
#include "io/printable.hpp"
#include "render/memory_budget.hpp"
#include "render/scene_vetting.hpp"

#include <spdlog/spdlog.h>

namespace fr {

CameraPath load_path_option(const SceneInfo& info, const std::string& file) {
  std::vector<PathProblem> problems;
  auto path = load_camera_path(file, info, &problems);
  if (!path) {
    std::string message = "--path: " + problems.front().to_string();
    if (problems.size() > 1) message += " (and " + std::to_string(problems.size() - 1) + " more)";
    throw UsageError(message);
  }
  return std::move(*path);
}

void apply_camera_path(const SceneInfo& info, const std::string& file, const ParsedOptions& options,
                       SceneState& state) {
  const CameraPath path = load_path_option(info, file);
  if (!options.has("time")) state.time_s = path.start_s();
  const PathSample sample = sample_camera_path(path, info, state.time_s);
  state.camera = sample.camera;
  state.camera_lo = sample.camera_lo;
  state.params = sample.params;
}

void check_memory(const RenderSettings& render, const DeviceInfo& device, bool all_passes) {
  const auto need = render_memory_need(render.width_px, render.height_px, all_passes);
  if (const std::string problem = memory_problem(need, device); !problem.empty())
    throw UsageError("--size " + std::to_string(render.width_px) + "x" +
                     std::to_string(render.height_px) + ": " + problem);
}

PreparedScene prepare_scene(const ParsedOptions& options, int max_side) {
  PreparedScene p;
  p.settings = load_settings(options);
  p.render = render_settings_from(p.settings, options, max_side);
  const auto folders = plugin_folders(p.settings, options);
  if (folders.empty())
    throw std::runtime_error("no plugin folder found (build the plugins, or pass --plugins DIR)");
  const auto outcomes = load_plugins(folders, p.settings.plugins);
  p.preset = preset_option(options, folders);
  if (p.preset) {
    apply_preset_settings(options, p.preset, p.settings);
    p.render = render_settings_from(p.settings, options, max_side);
  }
  p.scene = find_scene(outcomes, scene_id_option(options, p.preset));
  p.state = make_default_state(p.scene->info);
  if (auto t = options.get("time")) p.state.time_s = parse_finite("--time", *t);
  if (auto file = options.get("path")) apply_camera_path(p.scene->info, *file, options, p.state);
  apply_scene_overrides(p.scene->info, options, p.state, p.preset);
  p.device = choose_device(p.settings, options);
  if (p.render.precision == Precision::Double && !p.device.has_fp64)
    throw UsageError("--precision double: device " + p.device.name + " has no double precision");
  std::string error;
  p.instance = SceneInstance::create(p.scene, &error);
  if (!p.instance) throw std::runtime_error(error);
  // A DE that never returns would hold this process until render.watchdog_s (nothing cancels a
  // running kernel): first a test render in a child process, as the explorer does, once per file
  // content. Not with isolation "none", which keeps everything in one process for a debugger.
  if (p.settings.plugins.isolation != PluginIsolation::None) {
    const VetResult vet =
        vet_scene_once(p.scene->file, p.render, p.device.name, p.settings.plugins);
    if (!vet.ok) {
      const std::string message = "scene '" + p.scene->info.id + "' (" +
                                  printable(p.scene->file.string()) + "): " + vet.error;
      if (vet.timed_out) throw SceneHangError(message);
      throw std::runtime_error(message);
    }
  }
  p.worker = std::make_unique<RenderWorker>(
      p.device, command_worker_limits(p.settings.plugins, p.render.watchdog_s));
  p.worker->name_scene_file(p.scene->info.id, printable(p.scene->file.string()));
  return p;
}

void update_scene(PreparedScene& p, double time_s) {
  std::string error;
  if (!p.instance->update(p.state, time_s, &error)) throw std::runtime_error(error);
}

}  // namespace fr
