#include "cli/commands.hpp"
#include "cli/scene_setup.hpp"

#include <ostream>

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

}  // namespace

int command_list(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto specs = plugin_option_specs();
  specs.push_back({"help", nullptr, false, "show this help"});
  auto options = parse_options("list", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis list [--plugins DIR]\n\nLists every scene plugin found: id, version, "
           "parameters with their ranges, or why it failed to load.\n\n"
        << format_options(specs);
    return 0;
  }
  const Settings settings = load_settings(options);
  const auto folders = plugin_folders(settings, options);
  if (folders.empty()) {
    err << "fractalis: error: no plugin folder found (build the plugins, or pass --plugins DIR)\n";
    return 1;
  }
  for (const auto& f : folders) out << "plugin folder: " << f.string() << "\n";
  for (const auto& o : load_scene_folder(folders)) {
    if (!o.scene) {
      out << "\n"
          << o.file.filename().string() << ": FAILED (" << load_result_name(o.result)
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
  }
  return 0;
}

}  // namespace fr
