#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "io/log.hpp"
#include "io/printable.hpp"
#include "plugin/scene_instance.hpp"
#include "render/kernel_assembly.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <ostream>
#include <set>
#include <stdexcept>

namespace fr {
namespace {

std::string format_value(const ParamInfo& p, const fr_value& v) {
  auto num = [](double x) {
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  if (p.type == FR_PARAM_BOOL) return v.v[0] != 0 ? "true" : "false";
  if (p.component_count() == 1) return num(v.v[0]);
  return num(v.v[0]) + "," + num(v.v[1]) + "," + num(v.v[2]);
}

// What the scene's kernel contains with the current settings: the stages compiled in and left
// out, the DE library files it includes, and the parameters baked in as constants. This is
// "each scene's kernel contains only what it needs", made visible.
void describe_kernel(const SceneInfo& info, const RenderSettings& settings, std::ostream& out) {
  const int lanes = resolve_lanes(settings.lanes, nullptr);
  const KernelConfig config = make_kernel_config(info, settings, lanes);
  const AssembledKernel k = assemble_render_kernel(info, make_default_state(info).params, config);
  const fr_features all = all_optional_stages();
  out << "  kernel (lanes " << lanes << ", " << precision_name(config.precision) << "): stages "
      << stage_names(config.stages) << "; left out: " << stage_names(all & ~config.stages) << "\n";
  std::set<std::string> library;
  for (size_t at = k.source.find("#line 1 \"fr/"); at != std::string::npos;
       at = k.source.find("#line 1 \"fr/", at + 1)) {
    const size_t start = at + 9, end = k.source.find('"', start);
    library.insert(k.source.substr(start, end - start));
  }
  out << "  DE library files:";
  for (const auto& f : library) out << " " << f;
  out << (library.empty() ? " none\n" : "\n");
  out << "  baked in as constants:";
  bool any = false;
  for (const auto& p : info.params)
    if (p.specialized()) {
      out << " " << p.key << "=" << format_value(p, p.default_value);
      any = true;
    }
  out << (any ? "" : " none") << "; " << std::count(k.source.begin(), k.source.end(), '\n')
      << " lines of OpenCL C\n";
}

}  // namespace

int command_list(const std::vector<std::string>& args, std::ostream& out,
                 std::ostream& /*err: messages go to spdlog*/) {
  auto specs = plugin_option_specs();
  specs.push_back({"help", nullptr, false, "show this help"});
  auto options = parse_options("list", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis list [--plugins DIR] [--verbose]\n\nLists every scene plugin found: "
           "id, version, parameters with their ranges, or why it failed to load. Exits 1 when\n"
           "a plugin failed to load. With --verbose (-v), also what each scene's kernel\n"
           "compiles in: stages, DE library files, parameters baked in as constants.\n\n"
        << format_options(specs);
    return 0;
  }
  const Settings settings = load_settings(options);
  const auto folders = plugin_folders(settings, options);
  if (folders.empty()) {
    throw std::runtime_error("no plugin folder found (build the plugins, or pass --plugins DIR)");
  }
  for (const auto& f : folders) out << "plugin folder: " << f.string() << "\n";
  bool any_failed = false;
  for (const auto& o : load_scene_folder(folders, settings.plugins)) {
    if (!o.scene) {
      any_failed = true;
      out << "\n"
          << printable(o.file.filename().string()) << ": FAILED (" << load_result_name(o.result)
          << "): " << o.message << "\n";
      continue;
    }
    const SceneInfo& s = o.scene->info;
    out << "\n"
        << s.id << " " << s.version << " — " << s.name << "  (" << o.file.filename().string()
        << ")\n";
    if (!s.description.empty()) out << "  " << s.description << "\n";
    if (!s.author.empty() || !s.license.empty())
      out << "  by " << s.author << ", " << s.license << "\n";
    for (const auto& p : s.params) {
      out << "  --param " << p.key << "=" << format_value(p, p.default_value) << "  "
          << param_type_name(p.type) << " in [" << format_value(p, p.min_value) << ", "
          << format_value(p, p.max_value) << "]"
          << (p.flags & FR_PARAM_SPECIALIZE ? ", compiled in" : "")
          << (p.flags & FR_PARAM_ANIMATABLE ? ", animatable" : "") << "  " << p.description << "\n";
    }
    if (log_verbosity() == LogVerbosity::Verbose) describe_kernel(s, settings.render, out);
  }
  // A plugin that did not load is a failure a script should see (the listing still shows the
  // rest).
  return any_failed ? 1 : 0;
}

}  // namespace fr
