// `fractalis vet-scene --file FILE`: the explorer's test render of a new or rebuilt scene, run
// in a child process so that a DE that never returns hangs only this process, which the explorer
// then kills (render/scene_vetting.hpp). Loads the one file, creates, updates at time 0, renders.
#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "io/printable.hpp"
#include "worker/render_worker.hpp"

#include <spdlog/spdlog.h>

#include <ostream>
#include <stdexcept>

namespace fr {

int command_vet_scene(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto specs = scene_option_specs();
  specs.push_back({"file", "PLUGIN.so", false, "the scene plugin to test"});
  specs.push_back({"help", nullptr, false, "show this help"});
  auto options = parse_options("vet-scene", args, specs);
  const auto file = options.get("file");
  if (options.has("help") || !file) {
    (file ? out : err) << "usage: fractalis vet-scene --file PLUGIN.so [--size WxH] [--lanes N] "
                          "[--precision P]\n\nRenders one tiny frame of a scene plugin; the "
                          "explorer runs it before a scene that arrived by hot reload is used.\n";
    return file ? 0 : 2;
  }
  const Settings settings = load_settings(options);
  const LoadOutcome o = load_scene_plugin(*file, settings.plugins);
  if (!o.scene) {
    throw std::runtime_error(printable(*file) + ": " + o.message);
  }
  std::string error;
  auto instance = SceneInstance::create(o.scene, &error);
  SceneState state = make_default_state(o.scene->info);
  if (!instance || !instance->update(state, 0, &error)) {
    throw std::runtime_error(error);
  }
  // In a render worker of its own, with its build and memory limits (a compiler bomb must not
  // take this process, or the machine, with it) and the render's own limit
  // (plugins.vet_render_timeout_s: a DE that never returns ends it, status 3); the parent's
  // plugins.vet_timeout_s is the time limit of the whole test.
  RenderWorkerLimits limits =
      command_worker_limits(settings.plugins, settings.plugins.vet_render_timeout_s);
  limits.frame_setting = "plugins.vet_render_timeout_s";
  RenderWorker renderer(choose_device(settings, options), limits);
  renderer.name_scene_file(o.scene->info.id, printable(*file));
  RenderSettings render = render_settings_from(settings, options);
  renderer.render(o.scene->info, state, render);
  return 0;
}

}  // namespace fr
