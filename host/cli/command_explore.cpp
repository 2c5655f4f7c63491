#include "app/explorer.hpp"
#include "app/game_loop.hpp"
#include "cli/commands.hpp"
#include "cli/explorer_setup.hpp"
#include "platform/system_facts.hpp"
#include "app/scene_edit.hpp"
#include "io/cache_dirs.hpp"
#include "io/run_program.hpp"
#include "ui/overlay.hpp"
#include "ui/scene_browser_view.hpp"
#include "ui/window.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <ostream>
#include <thread>

namespace fr {

int command_explore(const std::vector<std::string>& args, std::ostream& out,
                    std::ostream& /*err: messages go to spdlog*/) {
  auto specs = scene_option_specs();
  specs.push_back({"frames", "N", false, "quit after N frames (for scripts and tests)"});
  specs.push_back(
      {"path", "FILE", false,
       "camera path to play from the start (P stops and replays it; K adds keyframes)"});
  specs.push_back({"fullscreen", nullptr, false, "start in fullscreen"});
  specs.push_back({"edit", "DIR", false,
                   "watch the scene project DIR (as `fractalis new` makes): a saved .cl shows at "
                   "once, a saved .c is rebuilt and reloaded"});
  specs.push_back({"help", nullptr, false, "show this help"});
  auto options = parse_options("explore", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis explore [--scene ID] [--size WxH] [options]\n\n"
           "Opens the explorer window. The overlay's Camera path section saves the keyframes\n"
           "added with the keys below for `fractalis animate`, and loads a path. Scenes dropped\n"
           "into the plugin folder appear while it runs; changed ones reload.\n\n"
           "keys (the defaults; [controls.keys] in the settings adds more):\n";
    const KeyBindings defaults = KeyBindings::defaults();
    for (const auto& row : kActionNames) {
      const std::string keys = defaults.label(row.value);
      out << "  " << keys << std::string(keys.size() < 28 ? 28 - keys.size() : 1, ' ') << row.label
          << "\n";
    }
    out << "\n" << format_options(specs);
    return 0;
  }
  const int64_t max_frames =
      options.has("frames") ? parse_integer("--frames", *options.get("frames"), 1, int64_t{1} << 40)
                            : -1;
  if (const std::string why = why_no_display(); !why.empty())
    throw std::runtime_error(why + "; use `fractalis render` instead");
  // Edit mode: the project's scene, watched (app/scene_edit.hpp).
  std::unique_ptr<SceneEdit> edit;
  if (const auto dir = options.get("edit")) {
    std::string error;
    const std::optional<SceneProject> project = read_scene_project(*dir, &error);
    if (!project) throw UsageError("--edit: " + error);
    if (!std::filesystem::exists(project->dir / "build" / "CMakeCache.txt"))
      throw UsageError("--edit: " + (project->dir / "build").string() +
                       " is not built: `fractalis new` builds a project, or cmake -S " +
                       project->dir.string() + " -B " + (project->dir / "build").string());
    const std::filesystem::path cmake = find_program_on_path("cmake");
    if (cmake.empty()) throw std::runtime_error("--edit: CMake is not on the PATH (apt-get install cmake)");
    if (options.has("scene") && *options.get("scene") != project->scene_id)
      throw UsageError("--edit: the project is scene '" + project->scene_id + "', not --scene " +
                       *options.get("scene"));
    options.values["scene"] = {project->scene_id};
    edit = std::make_unique<SceneEdit>(*project, cmake);
  }
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto now_s = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  // The window opens at once: scenes not vetted before are vetted while it shows what it is
  // preparing, the one to be shown first.
  ExplorerSetup setup =
      prepare_explorer(options, /*settings_problems_are_errors=*/false, /*vet_in_background=*/true);
  Explorer& explorer = *setup.explorer;
  const Settings& settings = setup.settings;
  const RenderSettings& render = settings.render;

  Window window("Fractalis", render.width_px, render.height_px,
                options.has("fullscreen") || settings.explorer.fullscreen);
  OverlayState overlay;
  // The scene browser: open at start when no scene was asked for.
  SceneBrowserOptions browser_options;
  if (const auto cache = fractalis_cache_dir(); !cache.empty())
    browser_options.cache_folder = cache / "thumbnails";
  SceneBrowser browser(setup.presets, setup.preset_problems, browser_options,
                       setup.worker->device(), explorer_worker_limits(settings.plugins));
  browser.set_visible(!setup.scene_asked);
  BrowserViewState browser_view;
  overlay.settings_file = user_settings_path();
  const KeyBindings bindings = KeyBindings::with_extra(settings.explorer.key_bindings);
  overlay.keys = bindings;
  bool mouse_captured = false;
  // When the window first showed anything, and first showed the scene (or the browser).
  double first_present_s = -1, first_frame_s = -1;
  bool browser_complete = false;

  LoopSteps steps;
  steps.now_s = now_s;
  // The browser is modal: while it is open, keys search and choose in it.
  steps.poll = [&](InputState& input) { window.poll(bindings, input, browser.visible()); };
  steps.update = [&](const InputState& input, double dt_s) {
    explorer.update(input, dt_s, now_s());
    for (Action a : explorer.pending_window_actions()) {
      if (a == Action::ToggleOverlay) overlay.visible = !overlay.visible;
      if (a == Action::ToggleFullscreen) window.set_fullscreen(!window.fullscreen());
      if (a == Action::Screenshot) overlay.screenshot_requested = true;
      if (a == Action::ToggleBrowser) browser.set_visible(!browser.visible());
    }
    browser.update(explorer.library(), explorer.render_settings());
    if (explorer.mouse_look() != mouse_captured) {
      mouse_captured = explorer.mouse_look();
      window.set_mouse_capture(mouse_captured);
    }
  };
  steps.render = [&] {
    // Behind the browser the last picture stays: the CPU goes to the browser's pictures.
    if (edit) {
      edit->poll(explorer, now_s());
      overlay.edit_status = edit->status();
      overlay.edit_failed = edit->failed();
    }
    const FrameView* image =
        browser.visible() ? nullptr : explorer.render(window.width_px(), window.height_px());
    // A frame of the scene: the browser, a picture (new or the parked view's last one), or the
    // scene's error; not the notice that it is still being prepared.
    const SceneSlot& slot = explorer.current();
    const bool shown = browser.visible() || (!slot.preparing && (image || slot.refused ||
                                                                  explorer.frames_rendered() > 0 ||
                                                                  !slot.error.empty()));
    window.present(image, [&] {
      if (browser.visible())
        draw_scene_browser(browser, explorer, window, browser_view);
      else
        draw_overlay(explorer, overlay);
    });
    if (overlay.screenshot_requested) {
      overlay.screenshot_requested = false;
      const int w =
          overlay.screenshot_at_window_size ? window.width_px() : overlay.screenshot_size[0];
      const int h =
          overlay.screenshot_at_window_size ? window.height_px() : overlay.screenshot_size[1];
      std::string error;
      if (explorer.screenshot(overlay.screenshot_file.data(), w, h, &error))
        spdlog::info("saved {} and its view, {} (--preset opens it)",
                     overlay.screenshot_file.data(),
                     screenshot_view_file(overlay.screenshot_file.data()).string());
      else
        spdlog::error("{}", error);
    }
    if (first_present_s < 0) first_present_s = now_s();
    if (browser.visible() && !browser_complete && browser.pending() == 0 &&
        browser.preparing_scenes() == 0) {
      browser_complete = true;
      spdlog::debug("every scene prepared and every picture of the browser in after {:.1f} s",
                    now_s());
    }
    if (shown && first_frame_s < 0) {
      first_frame_s = now_s();
      spdlog::debug("first frame after {:.2f} s", first_frame_s);
    }
    // Nothing left to refine: wait for input instead of spinning.
    if (!image) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return shown;
  };
  const int64_t frames = run_game_loop(steps, max_frames);
  out << "explored for " << frames << " frames";
  // For scripts that time the start (scripts/startup-time.sh): from the command's start.
  if (first_frame_s >= 0) {
    char times[128];
    std::snprintf(times, sizeof times,
                  " (the window showed something after %.2f s, the first frame after %.2f s)",
                  first_present_s, first_frame_s);
    out << times;
  }
  out << "\n";
  return 0;
}

}  // namespace fr
