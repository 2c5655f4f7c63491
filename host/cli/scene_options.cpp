#include "cli/scene_options.hpp"
#include "cli/preset_files.hpp"

#include "io/build_paths.hpp"
#include "io/echo.hpp"
#include "io/printable.hpp"
#include "platform/files.hpp"
#include "platform/user_folders.hpp"
#include "render/camera.hpp"
#include "render/kernel_cache.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdlib>
#include <ostream>

namespace fr {

OptionSpec config_option_spec() {
  return {"config", "FILE", false,
          "settings file (default: config.toml in your settings folder,\n"
          "                                 $XDG_CONFIG_HOME/fractalis or %APPDATA%\\fractalis)"};
}

std::vector<OptionSpec> plugin_option_specs() {
  return {
      {"plugins", "DIR", false, "scene plugin folder (instead of the configured ones)"},
      config_option_spec(),
  };
}

std::vector<OptionSpec> scene_option_specs() {
  auto specs = plugin_option_specs();
  const std::vector<OptionSpec> more = {
      {"scene", "ID", false, "scene to render (default: mandelbulb; see `fractalis list`)"},
      {"size", "WxH", false, "image size in pixels (default 1280x720)"},
      {"eye", "X,Y,Z", false, "camera position (default: the scene's)"},
      {"target", "X,Y,Z", false, "point the camera looks at"},
      {"up", "X,Y,Z", false,
       "camera up direction (default: the scene's); parallel to the view: a stable perpendicular"},
      {"fov", "DEG", false, "horizontal field of view in degrees, (0, 180)"},
      {"preset", "NAME|FILE", false,
       "start from a preset (values and view; `fractalis list` shows them), a preset file "
       "(.toml) or a Mandelbulber2 settings file (.fract, imported on the fly); --scene may be "
       "left "
       "out"},
      {"param", "KEY=VALUE", true, "set a scene parameter (repeatable); vec3 as x,y,z"},
      {"time", "SECONDS", false, "scene time for the update callback (default 0)"},
      {"lanes", "1|4|8|16|32|64", false,
       "rays per work-item (default: on CPUs 16, with AVX-512 64 in float and 32 in double; 1 on "
       "GPUs)"},
      {"precision", "auto|float|double|dd", false,
       "arithmetic precision of the kernel (default auto: double where float cannot resolve the "
       "view, dd (double-double) where double cannot and the scene has a pair estimate)"},
      {"samples", "N", false, "jittered samples per pixel, accumulated (anti-aliasing; default 1)"},
      {"integrator", "fast|path", false,
       "how light is computed: fast (direct light; default) or path (path tracing, with "
       "--samples)"},
      {"set", "KEY=VALUE", true,
       "any setting, as in config/default.toml (repeatable), e.g.\n"
       "                                 render.effects.fog=false"},
      {"device", "SEL", false, "OpenCL device: gpu, cpu, P:D or part of its name"},
  };
  specs.insert(specs.end(), more.begin(), more.end());
  return specs;
}

Settings load_settings(const ParsedOptions& options, std::vector<SettingsProblem>* collected) {
  Settings settings;
  std::optional<std::filesystem::path> file;
  if (auto given = options.get("config")) {
    file = *given;
    const PathInfo path = examine_path(*file);  // devices too (std::filesystem: not on Windows)
    const std::string named = "--config: '" + echo(file->string()) + "' ";
    switch (path.kind) {
      case PathKind::Regular:
        break;
      case PathKind::Missing:
        if (path.loops) throw UsageError(named + "is a symbolic link that loops");
        if (path.is_link) throw UsageError(named + "is a symbolic link to nothing");
        if (!path.error.empty()) throw UsageError(named + "cannot be read (" + path.error + ")");
        throw UsageError("--config: no such file '" + echo(file->string()) + "'");
      case PathKind::Folder:
        throw UsageError(named + "is a folder, not a settings file");
      case PathKind::CharacterDevice:
      case PathKind::BlockDevice:
        throw UsageError(named + "is a device, not a settings file");
      case PathKind::Pipe:
      case PathKind::Socket:
        throw UsageError(named + "is a pipe or socket, not a settings file");
      case PathKind::Other:
        throw UsageError(named + "cannot be read");
    }
  } else {
    file = user_settings_file();
  }
  auto report = [&](const std::vector<SettingsProblem>& problems) {
    if (problems.empty()) return;
    if (collected) {
      collected->insert(collected->end(), problems.begin(), problems.end());
      return;
    }
    std::string message = problems.front().to_string();
    if (problems.size() > 1) message += " (and " + std::to_string(problems.size() - 1) + " more)";
    throw UsageError(message);
  };
  if (file) report(load_settings_file(*file, settings));
  if (auto it = options.values.find("set"); it != options.values.end())
    for (const std::string& assignment : it->second)
      report(apply_setting_override(assignment, settings));
  return settings;
}

namespace {

// Whether the running executable is the build tree's (its scenes and paths are the build's and
// the source tree's), not an installed one (or the system does not say where it is). An
// installation is recognised by its own scenes beside it, wherever it lies: a package unpacked
// inside a build folder is still that package.
bool runs_from_build_tree(const std::filesystem::path& exe) {
  if (exe.empty()) return true;
  std::error_code ec;
  if (std::filesystem::is_directory(exe.parent_path().parent_path() / FRACTALIS_PLUGIN_INSTALL_DIR,
                                    ec))
    return false;
  // Folders compared as folders, not as strings: a Windows build run under Wine has a Linux
  // build root compiled in (/work/build) and a Windows path of its own (Z:\work\build\...).
  for (auto dir = exe.parent_path(); dir.has_relative_path(); dir = dir.parent_path())
    if (std::filesystem::equivalent(dir, build_paths::root, ec)) return true;
  return false;
}

}  // namespace

std::vector<std::filesystem::path> plugin_folders(const Settings& settings,
                                                  const ParsedOptions& options) {
  if (auto dir = options.get("plugins")) {
    std::error_code ec;
    if (!std::filesystem::is_directory(*dir, ec))
      throw UsageError("--plugins: '" + echo(*dir) + "' is not a folder");
    return {*dir};
  }
  if (!settings.plugin_folders.empty()) return settings.plugin_folders;
  std::vector<std::filesystem::path> folders;
  auto add = [&](const std::filesystem::path& dir) {
    std::error_code ec;
    if (std::filesystem::is_directory(dir, ec)) folders.push_back(dir);
  };
  // The scenes built with this executable: the build tree's when it runs from the build tree,
  // else the installed ones, found from the executable (<prefix>/bin/fractalis ->
  // <prefix>/lib/fractalis/plugins), so that any install prefix works.
  const std::filesystem::path exe = executable_path();
  // Normalised: one kind of separator on Windows too, where the compiled-in parts use '/'.
  if (runs_from_build_tree(exe))
    add(std::filesystem::path(build_paths::plugin_dir).lexically_normal());
  else
    add((exe.parent_path().parent_path() / FRACTALIS_PLUGIN_INSTALL_DIR).lexically_normal());
  add(user_scene_folder());
  return folders;
}

std::filesystem::path shipped_path_file(const std::string& name) {
  const std::filesystem::path exe = executable_path();
  if (runs_from_build_tree(exe))
    return (std::filesystem::path(build_paths::paths_dir) / name).lexically_normal();
  return (exe.parent_path().parent_path() / FRACTALIS_PATHS_INSTALL_DIR / name).lexically_normal();
}

std::filesystem::path shipped_folder(const std::filesystem::path& in_source_tree,
                                     const std::filesystem::path& installed) {
  const std::filesystem::path exe = executable_path();
  if (runs_from_build_tree(exe)) return in_source_tree.lexically_normal();
  return (exe.parent_path().parent_path() / installed).lexically_normal();
}

std::filesystem::path user_scene_folder() {
  const std::filesystem::path folder = user_folder(UserFolder::Data);
  return folder.empty() ? folder : folder / "scenes";
}

std::vector<LoadOutcome> load_plugins(const std::vector<std::filesystem::path>& folders,
                                      const PluginPolicy& policy) {
  auto outcomes = load_scene_folder(folders, policy);
  for (const auto& o : outcomes)
    if (o.result != LoadResult::Loaded)
      spdlog::warn("skipped plugin {}: {}", printable(o.file.string()), o.message);
  return outcomes;
}

namespace {

// Edits (insert, delete, replace) from a to b, giving up past `limit`.
size_t edit_distance(const std::string& a, const std::string& b, size_t limit) {
  if (a.size() > b.size() + limit || b.size() > a.size() + limit) return limit + 1;
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

UsageError unknown_scene(const std::string& id, const std::vector<std::string>& available) {
  std::string message = "unknown scene '" + echo(id) + "' (";
  if (available.empty()) return UsageError(message + "no scenes were found)");
  // A short list is given whole; a long one (the gallery has forty) by the ids that look like
  // what was typed, so the message stays one readable line.
  std::vector<std::string> shown;
  if (available.size() <= 12) {
    shown = available;
    message += "available: ";
  } else {
    const size_t limit = std::max<size_t>(2, id.size() / 3);
    std::vector<std::pair<size_t, std::string>> near;
    if (id.size() <= 64)
      for (const std::string& a : available) {
        const size_t d = a.find(id) != std::string::npos ? 0 : edit_distance(id, a, limit);
        if (d <= limit) near.emplace_back(d, a);
      }
    std::stable_sort(near.begin(), near.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (size_t i = 0; i < near.size() && i < 5; ++i) shown.push_back(near[i].second);
    message += std::to_string(available.size()) + " scenes, `fractalis list` shows them";
    if (!shown.empty()) message += "; did you mean: ";
  }
  for (size_t i = 0; i < shown.size(); ++i) {
    if (i) message += ", ";
    message += shown[i];
  }
  return UsageError(message + ")");
}

std::shared_ptr<const LoadedScene> find_scene(const std::vector<LoadOutcome>& outcomes,
                                              const std::string& id) {
  std::vector<std::string> available;
  for (const auto& o : outcomes) {
    if (!o.scene) continue;
    if (o.scene->info.id == id) return o.scene;
    available.push_back(o.scene->info.id);
  }
  throw unknown_scene(id, available);
}

namespace {

fr_value parse_param_value(const ParamInfo& p, const std::string& assignment,
                           const std::string& text) {
  const std::string what = "--param " + echo(assignment);
  fr_value v{};
  switch (p.type) {
    case FR_PARAM_BOOL:
      if (text == "true" || text == "1" || text == "on")
        v.v[0] = 1;
      else if (text == "false" || text == "0" || text == "off")
        v.v[0] = 0;
      else
        throw UsageError(what + ": expected true or false for bool parameter '" + p.key + "'");
      return v;
    case FR_PARAM_CHOICE: {
      // By name only: an index would silently mean something else when the scene reorders.
      const int index = p.choice_index(text);
      if (index < 0) {
        std::string names;
        for (const std::string& c : p.choices) {
          if (!names.empty()) names += ", ";
          names += c;
        }
        throw UsageError(what + ": '" + printable(text) + "' is not a value of '" + p.key +
                         "' (one of: " + names + ")");
      }
      v.v[0] = index;
      return v;
    }
    case FR_PARAM_INT:
      v.v[0] =
          static_cast<double>(parse_integer(what, text, static_cast<long long>(p.min_value.v[0]),
                                            static_cast<long long>(p.max_value.v[0])));
      return v;
    case FR_PARAM_FLOAT:
      v.v[0] = parse_finite(what, text);
      break;
    default: {
      auto xyz = parse_vec3(what, text);
      for (int i = 0; i < 3; ++i) v.v[i] = xyz[i];
    }
  }
  for (int i = 0; i < p.component_count(); ++i)
    if (v.v[i] < p.min_value.v[i] || v.v[i] > p.max_value.v[i])
      throw UsageError(what + ": " + text + " is outside the range of '" + p.key + "' [" +
                       std::to_string(p.min_value.v[i]) + ", " + std::to_string(p.max_value.v[i]) +
                       "]");
  return v;
}

}  // namespace

std::optional<Preset> preset_option(const ParsedOptions& options,
                                    const std::vector<std::filesystem::path>& folders) {
  const auto id = options.get("preset");
  if (!id) return std::nullopt;
  if (is_preset_path(*id)) return preset_from_path(*id);
  std::vector<PresetProblem> problems;
  const std::vector<Preset> presets = load_presets(folders, &problems);
  if (auto found = find_preset(presets, *id)) return found;
  for (const PresetProblem& p : problems)
    if (p.file.stem().string() == *id) throw UsageError("--preset " + echo(*id) + ": " + p.message);
  std::string names;
  for (const Preset& p : presets) {
    if (!names.empty()) names += ", ";
    names += p.id;
  }
  throw UsageError("--preset: no preset '" + echo(*id) +
                   "' (there are: " + (names.empty() ? std::string("none") : names) + ")");
}

void apply_preset_settings(const ParsedOptions& options, const std::optional<Preset>& preset,
                           Settings& settings) {
  if (!preset) return;
  const std::vector<std::string> problems = apply_preset_settings(*preset, settings);
  if (!problems.empty()) throw UsageError("--preset " + echo(preset->id) + ": " + problems.front());
  // The command line has the last word.
  if (auto it = options.values.find("set"); it != options.values.end())
    for (const std::string& assignment : it->second) apply_setting_override(assignment, settings);
}

std::string scene_id_option(const ParsedOptions& options, const std::optional<Preset>& preset) {
  const auto scene = options.get("scene");
  if (preset && scene && *scene != preset->scene_id)
    throw UsageError("--preset " + preset->id + " is for scene '" + preset->scene_id +
                     "', not --scene " + echo(*scene));
  if (preset) return preset->scene_id;
  return scene.value_or("mandelbulb");
}

void apply_scene_overrides(const SceneInfo& info, const ParsedOptions& options, SceneState& state,
                           const std::optional<Preset>& preset) {
  if (preset) {
    const std::vector<std::string> problems = apply_preset(*preset, info, state);
    if (!problems.empty()) {
      std::string message = "--preset " + preset->id + ": " + problems.front();
      if (problems.size() > 1) message += " (and " + std::to_string(problems.size() - 1) + " more)";
      throw UsageError(message);
    }
  }
  if (auto it = options.values.find("param"); it != options.values.end()) {
    for (const std::string& assignment : it->second) {
      auto eq = assignment.find('=');
      if (eq == std::string::npos)
        throw UsageError("--param " + echo(assignment) + ": expected KEY=VALUE");
      const std::string key = assignment.substr(0, eq);
      int index = info.find_param(key);
      if (index < 0) {
        std::string keys;
        for (const auto& p : info.params) keys += (keys.empty() ? "" : ", ") + p.key;
        throw UsageError("--param " + echo(assignment) + ": scene '" + info.id +
                         "' has no parameter '" + key +
                         "' (it has: " + (keys.empty() ? "none" : keys) + ")");
      }
      state.params[index] =
          parse_param_value(info.params[index], assignment, assignment.substr(eq + 1));
    }
  }
  // The eye and target keep every digit a double-double holds (deep views, docs/deep_zoom.md).
  const auto set_pairs = [&](const char* option, double hi[3], double lo[3]) {
    const auto text = options.get(option);
    if (!text) return;
    const std::string what = std::string("--") + option;
    int digits = 0;
    const std::array<DoubleDouble, 3> v = parse_vec3_pairs(what, *text, &digits);
    for (int i = 0; i < 3; ++i) {
      hi[i] = v[i].hi;
      lo[i] = v[i].lo;
    }
    if (digits > kPairDigits)
      spdlog::warn(
          "{}: a number with {} significant digits; a double-double keeps about 32, and "
          "the rest is dropped",
          what, digits);
  };
  set_pairs("eye", state.camera.eye, state.camera_lo.eye);
  set_pairs("target", state.camera.target, state.camera_lo.target);
  if (auto up = options.get("up")) {
    auto v = parse_vec3("--up", *up);
    if (v[0] == 0 && v[1] == 0 && v[2] == 0) throw UsageError("--up: 0,0,0 has no direction");
    std::copy(v.begin(), v.end(), state.camera.up);
  }
  if (auto fov = options.get("fov")) state.camera.fov_deg = parse_finite("--fov", *fov);
  if (auto problem = check_camera(state.camera, state.camera_lo))
    throw UsageError("camera: " + *problem);
}

RenderSettings render_settings_from(const Settings& settings, const ParsedOptions& options,
                                    int max_side) {
  RenderSettings r = settings.render;
  if (auto size = options.get("size")) {
    auto wh = parse_size("--size", *size, max_side);
    r.width_px = wh[0];
    r.height_px = wh[1];
  }
  if (auto lanes = options.get("lanes")) {
    long long n = parse_integer("--lanes", *lanes, 1, 64);
    if (n != 1 && n != 4 && n != 8 && n != 16 && n != 32 && n != 64)
      throw UsageError("--lanes: expected 1, 4, 8, 16, 32 or 64, got " + echo(*lanes));
    r.lanes = static_cast<int>(n);
  }
  if (auto samples = options.get("samples"))
    r.samples = static_cast<int>(parse_integer("--samples", *samples, 1, 4096));
  if (auto integrator = options.get("integrator")) {
    const auto i = enum_from_name<Integrator>(*integrator);
    if (!i)
      throw UsageError("--integrator: expected " + enum_name_list<Integrator>() + ", got '" +
                       echo(*integrator) + "'");
    r.integrator = *i;
  }
  if (auto precision = options.get("precision")) {
    const auto p = enum_from_name<Precision>(*precision);
    if (!p)
      throw UsageError("--precision: expected " + enum_name_list<Precision>() + ", got '" +
                       echo(*precision) + "'");
    r.precision = *p;
  }
  return r;
}

DeviceInfo choose_device(const Settings& settings, const ParsedOptions& options) {
  // OpenCL work starts here: first keep the compiled-kernel cache within its bound.
  if (kernel_cache_is_ours())
    trim_kernel_cache(kernel_cache_dir(), static_cast<uint64_t>(settings.cache.kernel_cache_mib)
                                              << 20);
  const std::string selector = options.get("device").value_or(settings.device);
  const auto devices = list_devices();
  if (devices.empty())
    throw std::runtime_error(
        "no OpenCL device found (is an ICD such as pocl-opencl-icd installed?)");
  std::string error;
  auto device = select_device(devices, selector, &error);
  if (!device) throw UsageError(error);
  return *device;
}

}  // namespace fr
