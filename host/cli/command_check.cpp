// `fractalis check PLUGIN.so [--json FILE]`: the conformance checks of check/scene_check.hpp on
// one scene plugin, as a table (and JSON). Exit 0 when nothing failed (warnings allowed), 1 when
// a check failed, 2 for usage errors.
#include "check/scene_check.hpp"
#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "io/atomic_file.hpp"

#include <spdlog/spdlog.h>

#include <optional>
#include <ostream>
#include <stdexcept>

namespace fr {

int command_check(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<OptionSpec> specs = {
      {"json", "FILE", false, "also write the findings as JSON (atomically)"},
      config_option_spec(),
      {"set", "KEY=VALUE", true, "any setting, as in config/default.toml (repeatable)"},
      {"device", "SEL", false, "OpenCL device: gpu, cpu, P:D or part of its name"},
      {"preset", "NAME", false,
       "check at this preset's values and view (from the presets/ folder beside the plugin or "
       "the plugin folders)"},
      {"help", nullptr, false, "show this help"},
  };
  // The plugin file comes first; the options after it.
  std::vector<std::string> rest = args;
  std::optional<std::filesystem::path> file;
  if (!rest.empty() && rest[0].rfind("--", 0) != 0) {
    file = rest[0];
    rest.erase(rest.begin());
  }
  auto options = parse_options("check", rest, specs);
  if (options.has("help")) {
    out << "usage: fractalis check PLUGIN.so [--json FILE] [--device SEL] [--preset NAME]\n\n"
           "Runs the conformance checks on a scene plugin (in a scene-host process, so a crash "
           "is a\nfinding): descriptor rules, DE builds, DE values (finite, Lipschitz, never "
           "longer than\nthe distance to the surface, bounded, the same at every lane width and "
           "precision),\nupdate determinism and parameter ranges, create/destroy leaks, a sanity "
           "render and a\ncareful one, and unloading. Exit 0 when nothing failed.\n\n"
        << format_options(specs);
    return 0;
  }
  if (!file) throw UsageError("expected a plugin file first (fractalis check PLUGIN.so)");
  const auto json_file = options.get("json");
  if (json_file) check_output_file("--json", *json_file);
  const Settings settings = load_settings(options);
  CheckOptions check;
  check.policy = settings.plugins;
  check.render = render_settings_from(settings, options);
  if (options.has("preset")) {
    std::vector<std::filesystem::path> folders = {file->parent_path()};
    for (const auto& f : plugin_folders(settings, options)) folders.push_back(f);
    check.preset = preset_option(options, folders);
  }
  // Every kernel of the plugin compiles and runs in a render worker: a DE that crashes it fails
  // the check it was in, and the next check starts a fresh worker.
  RenderWorker worker(choose_device(settings, options),
                      command_worker_limits(settings.plugins, check.render.watchdog_s));
  const CheckReport report = check_scene_plugin(*file, check, worker);
  write_check_table(report, json_file && is_standard_output(*json_file) ? err : out);
  if (json_file) {
    std::string error;
    if (!write_file_atomic(*json_file, check_report_json(report), &error)) {
      throw std::runtime_error(error);
    }
  }
  return report.failed() ? 1 : 0;
}

}  // namespace fr
