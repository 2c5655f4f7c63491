#include "settings/settings.hpp"

#include "render/kernel_assembly.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

namespace fr {
namespace {

// One settings key: how to apply its value, or why the value is wrong ("" when it applied).
struct Key {
  const char* name;
  std::function<std::string(const toml::node&, Settings&)> apply;
};

std::string set_int(const toml::node& n, int& out, long long lo, long long hi) {
  auto v = n.value<int64_t>();
  if (!n.is_integer() || !v || *v < lo || *v > hi)
    return "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  out = static_cast<int>(*v);
  return "";
}

std::string set_float(const toml::node& n, float& out, double lo, double hi, bool lo_open = false) {
  auto v = n.value<double>();
  std::ostringstream range;
  range << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
  if (!n.is_number() || !v || !(lo_open ? *v > lo : *v >= lo) || !(*v <= hi))
    return "expected a number in " + range.str();
  out = static_cast<float>(*v);
  return "";
}

std::string set_double(const toml::node& n, double& out, double lo, double hi,
                       bool lo_open = false) {
  float v = static_cast<float>(out);
  std::string error = set_float(n, v, lo, hi, lo_open);
  if (error.empty()) out = *n.value<double>();
  return error;
}

template <typename Enum>
std::string set_choice(const toml::node& n, Enum& out,
                       std::initializer_list<std::pair<const char*, Enum>> choices) {
  auto v = n.value<std::string>();
  std::string names;
  for (const auto& [name, value] : choices) {
    names += (names.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    if (v && *v == name) {
      out = value;
      return "";
    }
  }
  return "expected one of " + names;
}

std::string set_effect(const toml::node& n, Settings& s, fr_features feature) {
  if (!n.is_boolean()) return "expected true or false";
  if (*n.value<bool>())
    s.render.disabled_stages &= ~feature;
  else
    s.render.disabled_stages |= feature;
  return "";
}

const std::vector<Key>& known_keys() {
  static const std::vector<Key> keys = {
      {"plugins.folders",
       [](const toml::node& n, Settings& s) -> std::string {
         const auto* arr = n.as_array();
         if (!arr) return "expected an array of folder paths";
         std::vector<std::filesystem::path> folders;
         for (const auto& item : *arr) {
           if (!item.is_string()) return "expected strings (folder paths)";
           folders.emplace_back(item.as_string()->get());
         }
         s.plugin_folders = folders;
         return "";
       }},
      {"plugins.isolation",
       [](const toml::node& n, Settings& s) {
         return set_choice(
             n, s.plugins.isolation,
             {{"process", PluginIsolation::Process}, {"none", PluginIsolation::None}});
       }},
      {"plugins.load_timeout_s",
       [](const toml::node& n, Settings& s) {
         return set_double(n, s.plugins.load_timeout_s, 0, 3600, true);
       }},
      {"plugins.call_timeout_s",
       [](const toml::node& n, Settings& s) {
         return set_double(n, s.plugins.call_timeout_s, 0, 3600, true);
       }},
      {"plugins.vet_timeout_s",
       [](const toml::node& n, Settings& s) {
         return set_double(n, s.plugins.vet_timeout_s, 0, 3600, true);
       }},
      {"plugins.allow_writable",
       [](const toml::node& n, Settings& s) {
         if (!n.is_boolean()) return std::string("expected true or false");
         s.plugins.allow_writable = *n.value<bool>();
         return std::string();
       }},
      {"device.select",
       [](const toml::node& n, Settings& s) -> std::string {
         if (!n.is_string())
           return "expected a string: \"\", \"gpu\", \"cpu\", \"P:D\" or part of a name";
         s.device = n.as_string()->get();
         return "";
       }},
      {"render.lanes",
       [](const toml::node& n, Settings& s) -> std::string {
         auto v = n.value<int64_t>();
         if (!n.is_integer() || !v || (*v != 0 && *v != 1 && *v != 4 && *v != 8 && *v != 16))
           return "expected one of 0 (device's choice), 1, 4, 8, 16";
         s.render.lanes = static_cast<int>(*v);
         return "";
       }},
      {"render.precision",
       [](const toml::node& n, Settings& s) {
         return set_choice(n, s.render.precision,
                           {{"auto", Precision::Auto},
                            {"float", Precision::Float},
                            {"double", Precision::Double}});
       }},
      {"render.samples",
       [](const toml::node& n, Settings& s) { return set_int(n, s.render.samples, 1, 4096); }},
      {"render.max_steps",
       [](const toml::node& n, Settings& s) { return set_int(n, s.render.max_steps, 1, 10000); }},
      {"render.max_bounces",
       [](const toml::node& n, Settings& s) { return set_int(n, s.render.max_bounces, 0, 8); }},
      {"render.hit_threshold_k",
       [](const toml::node& n, Settings& s) {
         return set_float(n, s.render.hit_threshold_k, 0, 100, true);
       }},
      {"render.exposure",
       [](const toml::node& n, Settings& s) {
         return set_float(n, s.render.exposure, 0, 100, true);
       }},
      {"render.ao_strength",
       [](const toml::node& n, Settings& s) {
         return set_float(n, s.render.ao_strength, 0, 100, true);
       }},
      {"render.relaxation",
       [](const toml::node& n, Settings& s) { return set_float(n, s.render.relaxation, 1, 1.95); }},
      {"render.shadow_max_steps",
       [](const toml::node& n, Settings& s) {
         return set_int(n, s.render.shadow_max_steps, 1, 10000);
       }},
      {"render.watchdog_s",
       [](const toml::node& n, Settings& s) { return set_double(n, s.render.watchdog_s, 0, 1e6); }},
      {"render.refine_steps",
       [](const toml::node& n, Settings& s) { return set_int(n, s.render.refine_steps, 0, 8); }},
      {"render.fast_math",
       [](const toml::node& n, Settings& s) {
         if (!n.is_boolean()) return std::string("expected true or false");
         s.render.fast_math = *n.value<bool>();
         return std::string();
       }},
      {"render.ao_reference_steps",
       [](const toml::node& n, Settings& s) {
         return set_int(n, s.render.ao_reference_steps, 1, 100000);
       }},
      {"render.roughness",
       [](const toml::node& n, Settings& s) { return set_float(n, s.render.roughness, 0, 1.5); }},
      {"render.reflectivity",
       [](const toml::node& n, Settings& s) { return set_float(n, s.render.reflectivity, 0, 1); }},
      {"render.aperture",
       [](const toml::node& n, Settings& s) {
         return set_float(n, s.render.aperture_radius, 0, 10);
       }},
      {"render.focus_distance",
       [](const toml::node& n, Settings& s) {
         return set_float(n, s.render.focus_distance, 0, 1000);
       }},
      {"render.shading_model",
       [](const toml::node& n, Settings& s) {
         return set_choice(n, s.render.shading,
                           {{"lambert", ShadingModel::Lambert},
                            {"blinn-phong", ShadingModel::BlinnPhong},
                            {"oren-nayar", ShadingModel::OrenNayar}});
       }},
      {"render.normal_method",
       [](const toml::node& n, Settings& s) {
         return set_choice(n, s.render.normals,
                           {{"tetrahedron", NormalMethod::Tetrahedron},
                            {"central", NormalMethod::CentralDifferences}});
       }},
      {"render.ao_method",
       [](const toml::node& n, Settings& s) {
         return set_choice(n, s.render.ao_method,
                           {{"step-count", AoMethod::StepCount}, {"sampled", AoMethod::Sampled}});
       }},
      {"render.shadow_method",
       [](const toml::node& n, Settings& s) {
         return set_choice(n, s.render.shadow_method,
                           {{"hard", ShadowMethod::Hard}, {"soft", ShadowMethod::Soft}});
       }},
      {"render.fog_method",
       [](const toml::node& n, Settings& s) {
         return set_choice(
             n, s.render.fog_method,
             {{"power", FogMethod::PowerLaw}, {"exponential", FogMethod::Exponential}});
       }},
      {"render.effects.shadows",
       [](const toml::node& n, Settings& s) { return set_effect(n, s, FR_FEATURE_SHADOWS); }},
      {"render.effects.ao",
       [](const toml::node& n, Settings& s) { return set_effect(n, s, FR_FEATURE_AO); }},
      {"render.effects.glow",
       [](const toml::node& n, Settings& s) { return set_effect(n, s, FR_FEATURE_GLOW); }},
      {"render.effects.fog",
       [](const toml::node& n, Settings& s) { return set_effect(n, s, FR_FEATURE_FOG); }},
      {"render.effects.reflections",
       [](const toml::node& n, Settings& s) { return set_effect(n, s, FR_FEATURE_REFLECTIONS); }},
      {"render.effects.dof",
       [](const toml::node& n, Settings& s) { return set_effect(n, s, kStageDepthOfField); }},
      {"window.width",
       [](const toml::node& n, Settings& s) {
         return set_int(n, s.explorer.window_width_px, 64, 16384);
       }},
      {"window.height",
       [](const toml::node& n, Settings& s) {
         return set_int(n, s.explorer.window_height_px, 64, 16384);
       }},
      {"window.fullscreen",
       [](const toml::node& n, Settings& s) -> std::string {
         if (!n.is_boolean()) return "expected true or false";
         s.explorer.fullscreen = *n.value<bool>();
         return "";
       }},
      {"explorer.target_fps",
       [](const toml::node& n, Settings& s) {
         return set_double(n, s.explorer.target_fps, 1, 240);
       }},
      {"explorer.quality",
       [](const toml::node& n, Settings& s) {
         return set_choice(n, s.explorer.full_quality_samples,
                           {{"fast", 2}, {"balanced", 8}, {"high", 32}});
       }},
      {"controls.mouse_sensitivity",
       [](const toml::node& n, Settings& s) {
         return set_double(n, s.explorer.mouse_sensitivity_deg_per_px, 0, 10, true);
       }},
      {"controls.invert_y",
       [](const toml::node& n, Settings& s) -> std::string {
         if (!n.is_boolean()) return "expected true or false";
         s.explorer.invert_y = *n.value<bool>();
         return "";
       }},
      {"controls.speed", [](const toml::node& n,
                            Settings& s) { return set_double(n, s.explorer.speed, 0, 100, true); }},
      // controls.keys is a table of action = "key name"; apply_key_bindings checks it.
  };
  return keys;
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

// The explorer's actions that keys can be bound to (app/input.cpp implements them).
const char* const kActionNames[] = {"move_forward",   "move_back",  "move_left",  "move_right",
                                    "move_up",        "move_down",  "speed_up",   "mouse_look",
                                    "camera_mode",    "overlay",    "fullscreen", "next_scene",
                                    "previous_scene", "screenshot", "quit"};

void apply_key_bindings(const toml::node& node, const std::string& file, Settings& s,
                        std::vector<SettingsProblem>& problems) {
  const auto* table = node.as_table();
  if (!table) {
    problems.push_back({file, static_cast<int>(node.source().begin.line), "controls.keys",
                        "expected a table of action = \"key name\""});
    return;
  }
  for (const auto& [action, value] : *table) {
    const std::string key = "controls.keys." + std::string(action.str());
    const int line = static_cast<int>(value.source().begin.line);
    const bool known = std::any_of(std::begin(kActionNames), std::end(kActionNames),
                                   [&](const char* a) { return action.str() == a; });
    if (!known) {
      std::string names;
      for (const char* a : kActionNames) names += (names.empty() ? "" : ", ") + std::string(a);
      problems.push_back({file, line, key, "unknown action (expected one of " + names + ")"});
    } else if (!value.is_string() || value.as_string()->get().empty()) {
      problems.push_back({file, line, key, "expected a key name such as \"W\" or \"Left Shift\""});
    } else {
      s.explorer.key_bindings[value.as_string()->get()] = std::string(action.str());
    }
  }
}

bool is_key_prefix(const std::string& prefix) {
  if (prefix == "controls") return true;
  return std::any_of(known_keys().begin(), known_keys().end(),
                     [&](const Key& k) { return std::string(k.name).rfind(prefix + ".", 0) == 0; });
}

// Applies every leaf of `table`, reporting unknown keys and bad values.
void apply_table(const toml::table& table, const std::string& prefix, const std::string& file,
                 Settings& s, std::vector<SettingsProblem>& problems) {
  for (const auto& [k, node] : table) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    const int line = static_cast<int>(node.source().begin.line);
    if (key == "controls.keys") {
      apply_key_bindings(node, file, s, problems);
      continue;
    }
    if (const auto* sub = node.as_table(); sub && is_key_prefix(key)) {
      apply_table(*sub, key, file, s, problems);
      continue;
    }
    const auto it = std::find_if(known_keys().begin(), known_keys().end(),
                                 [&](const Key& known) { return key == known.name; });
    if (it == known_keys().end()) {
      problems.push_back(
          {file, line, key, "unknown key (did you mean '" + nearest_known_key(key) + "'?)"});
      continue;
    }
    if (std::string error = it->apply(node, s); !error.empty())
      problems.push_back({file, line, key, error});
  }
}

// Deepest nesting a settings text may have: the parser recurses once per level of arrays,
// inline tables and dotted key parts, so tens of thousands of levels exhaust the stack. The
// known keys are at most three levels deep.
constexpr int kMaxTomlNesting = 64;

// Why `text` nests too deeply to parse safely (the line and how deep), or "". Brackets, braces
// and dots inside strings and comments do not count.
std::string nesting_problem(const std::string& text, int* line_out) {
  int depth = 0, dots = 0, line = 1;
  char quote = 0;
  bool comment = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      dots = 0;
      comment = false;
      if (quote == '"' || quote == '\'') quote = 0;  // single-line strings end here anyway
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (c == '\\' && quote == '"')
        ++i;
      else if (c == quote)
        quote = 0;
      continue;
    }
    if (c == '#')
      comment = true;
    else if (c == '"' || c == '\'')
      quote = c;
    else if (c == '[' || c == '{')
      ++depth;
    else if (c == ']' || c == '}')
      depth = depth > 0 ? depth - 1 : 0;
    else if (c == '.' && !(i > 0 && std::isdigit(static_cast<unsigned char>(text[i - 1]))))
      ++dots;
    if (depth > kMaxTomlNesting || dots > kMaxTomlNesting) {
      *line_out = line;
      return "nested more than " + std::to_string(kMaxTomlNesting) +
             " levels deep (arrays, inline tables or dotted key parts); settings are at most 3 "
             "deep, so this is not a settings file";
    }
  }
  return "";
}

std::vector<SettingsProblem> apply_toml(const std::string& text, const std::string& file,
                                        Settings& s) {
  std::vector<SettingsProblem> problems;
  int deep_line = 0;
  if (std::string why = nesting_problem(text, &deep_line); !why.empty()) {
    problems.push_back({file, deep_line, "", why});
    return problems;
  }
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    problems.push_back({file, static_cast<int>(e.source().begin.line), "",
                        "not valid TOML: " + std::string(e.description())});
    return problems;
  }
  apply_table(root, "", file, s, problems);
  std::stable_sort(
      problems.begin(), problems.end(),
      [](const SettingsProblem& a, const SettingsProblem& b) { return a.line < b.line; });
  return problems;
}

}  // namespace

std::string SettingsProblem::to_string() const {
  return file + (line > 0 ? ":" + std::to_string(line) : "") + ": " +
         (key.empty() ? "" : "key '" + key + "': ") + message;
}

std::string nearest_known_key(const std::string& key) {
  std::string best;
  size_t best_d = ~size_t{0};
  for (const Key& known : known_keys()) {
    size_t d = edit_distance(key, known.name);
    if (d < best_d) best_d = d, best = known.name;
  }
  return best;
}

std::string format_settings_toml(const Settings& s) {
  auto choice = [](int v, std::initializer_list<const char*> names) {
    return "\"" + std::string(*(names.begin() + v)) + "\"";
  };
  auto on = [&](fr_features f) { return (s.render.disabled_stages & f) ? "false" : "true"; };
  std::ostringstream out;
  out << "# Fractalis settings, written by the explorer. See config/default.toml for every "
         "key.\n\n";
  out << "[plugins]\nfolders = [";
  for (size_t i = 0; i < s.plugin_folders.size(); ++i)
    out << (i ? ", " : "") << toml::value<std::string>(s.plugin_folders[i].string());
  out << "]\nisolation = "
      << (s.plugins.isolation == PluginIsolation::None ? "\"none\"" : "\"process\"")
      << "\nload_timeout_s = " << s.plugins.load_timeout_s
      << "\ncall_timeout_s = " << s.plugins.call_timeout_s
      << "\nvet_timeout_s = " << s.plugins.vet_timeout_s
      << "\nallow_writable = " << (s.plugins.allow_writable ? "true" : "false");
  out << "\n\n[device]\nselect = " << toml::value<std::string>(s.device) << "\n\n";
  const RenderSettings& r = s.render;
  out << "[render]\nlanes = " << r.lanes << "\nprecision = \"" << precision_name(r.precision)
      << "\""
      << "\nsamples = " << r.samples << "\nmax_steps = " << r.max_steps
      << "\nmax_bounces = " << r.max_bounces << "\nhit_threshold_k = " << r.hit_threshold_k
      << "\nexposure = " << r.exposure << "\nao_strength = " << r.ao_strength
      << "\nao_reference_steps = " << r.ao_reference_steps << "\nrelaxation = " << r.relaxation
      << "\nfast_math = " << (r.fast_math ? "true" : "false") << "\nwatchdog_s = " << r.watchdog_s
      << "\nrefine_steps = " << r.refine_steps << "\nshadow_max_steps = " << r.shadow_max_steps
      << "\nroughness = " << r.roughness << "\nreflectivity = " << r.reflectivity
      << "\naperture = " << r.aperture_radius << "\nfocus_distance = " << r.focus_distance
      << "\nshading_model = "
      << choice(static_cast<int>(r.shading), {"lambert", "blinn-phong", "oren-nayar"})
      << "\nnormal_method = " << choice(static_cast<int>(r.normals), {"tetrahedron", "central"})
      << "\nao_method = " << choice(static_cast<int>(r.ao_method), {"step-count", "sampled"})
      << "\nshadow_method = " << choice(static_cast<int>(r.shadow_method), {"hard", "soft"})
      << "\nfog_method = " << choice(static_cast<int>(r.fog_method), {"power", "exponential"})
      << "\n\n";
  out << "[render.effects]\nshadows = " << on(FR_FEATURE_SHADOWS) << "\nao = " << on(FR_FEATURE_AO)
      << "\nglow = " << on(FR_FEATURE_GLOW) << "\nfog = " << on(FR_FEATURE_FOG)
      << "\nreflections = " << on(FR_FEATURE_REFLECTIONS) << "\ndof = " << on(kStageDepthOfField)
      << "\n\n";
  const ExplorerSettings& e = s.explorer;
  out << "[window]\nwidth = " << e.window_width_px << "\nheight = " << e.window_height_px
      << "\nfullscreen = " << (e.fullscreen ? "true" : "false") << "\n\n";
  const char* quality = e.full_quality_samples <= 2   ? "fast"
                        : e.full_quality_samples <= 8 ? "balanced"
                                                      : "high";
  out << "[explorer]\ntarget_fps = " << e.target_fps << "\nquality = \"" << quality << "\"\n\n";
  out << "[controls]\nmouse_sensitivity = " << e.mouse_sensitivity_deg_per_px
      << "\ninvert_y = " << (e.invert_y ? "true" : "false") << "\nspeed = " << e.speed << "\n";
  if (!e.key_bindings.empty()) {
    out << "\n[controls.keys]\n";
    for (const auto& [key, action] : e.key_bindings)
      out << action << " = " << toml::value<std::string>(key) << "\n";
  }
  return out.str();
}

std::vector<std::string> known_setting_keys() {
  std::vector<std::string> names;
  for (const Key& k : known_keys()) names.emplace_back(k.name);
  return names;
}

std::filesystem::path user_settings_path() {
  std::filesystem::path base;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    base = xdg;
  else if (const char* home = std::getenv("HOME"); home && *home)
    base = std::filesystem::path(home) / ".config";
  else
    return {};
  return base / "fractalis" / "config.toml";
}

std::optional<std::filesystem::path> user_settings_file() {
  const auto file = user_settings_path();
  if (file.empty()) return std::nullopt;
  std::error_code ec;
  if (std::filesystem::is_regular_file(file, ec)) return file;
  return std::nullopt;
}

std::vector<SettingsProblem> load_settings_file(const std::filesystem::path& file, Settings& s) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {{file.string(), 0, "", "cannot read the file"}};
  std::stringstream text;
  text << in.rdbuf();
  return apply_toml(text.str(), file.string(), s);
}

std::vector<SettingsProblem> apply_setting_override(const std::string& assignment, Settings& s) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos)
    return {{"--set", 0, "", "expected KEY=VALUE, got '" + assignment + "'"}};
  std::string key = assignment.substr(0, eq), value = assignment.substr(eq + 1);
  // Bare words are strings ("--set render.shading_model=lambert"); numbers, booleans, quoted
  // strings and arrays pass as TOML.
  const bool bare_word = !value.empty() && value.find_first_of("\"[{") == std::string::npos &&
                         value != "true" && value != "false" &&
                         value.find_first_not_of("+-.0123456789eE_") != std::string::npos;
  if (bare_word) value = "\"" + value + "\"";
  auto problems = apply_toml(key + " = " + value + "\n", "--set " + assignment, s);
  for (auto& p : problems) p.line = 0;
  return problems;
}

}  // namespace fr
