#include "path/preset.hpp"

#include "io/echo.hpp"
#include "io/toml_guard.hpp"
#include "path/toml_values.hpp"
#include "scene/vec3.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace fr {
namespace {

bool is_preset_id(const std::string& s) {
  if (s.empty() || s.size() > 63 || !(s[0] >= 'a' && s[0] <= 'z')) return false;
  for (char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return false;
  return true;
}

std::string where(const std::filesystem::path& file, int line) {
  std::string out = file.string();
  if (line > 0) out.append(":").append(std::to_string(line));
  return out.append(": ");
}

// Parses a preset's text; nullopt (with a problem) when it is not TOML or nests too deep.
std::optional<toml::table> parse(const std::string& text, const std::filesystem::path& file,
                                 std::vector<std::string>* problems) {
  int deep_line = 0;
  if (std::string why = toml_nesting_problem(text, &deep_line); !why.empty()) {
    problems->push_back(where(file, deep_line) + why);
    return std::nullopt;
  }
  try {
    return toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    problems->push_back(where(file, static_cast<int>(e.source().begin.line)) +
                        "not valid TOML: " + std::string(e.description()));
    return std::nullopt;
  }
}

const char* const kTopKeys[] = {"scene", "name", "description", "params", "camera", "settings",
                                "lights"};
const char* const kLightKeys[] = {"direction", "position", "color", "intensity", "attenuation",
                                  "falloff"};
const char* const kLightKeysText = "direction or position, color, intensity, attenuation, falloff";
const char* const kCameraKeys[] = {"eye", "target", "up", "fov_deg"};

}  // namespace

std::optional<Preset> preset_from_text(const std::string& text, const std::filesystem::path& file,
                                       const std::string& id, std::vector<std::string>* problems) {
  auto problem = [&](int line, const std::string& what) {
    problems->push_back(where(file, line) + what);
  };
  auto root = parse(text, file, problems);
  if (!root) return std::nullopt;
  bool ok = true;
  for (const auto& [key, node] : *root)
    if (std::find(std::begin(kTopKeys), std::end(kTopKeys), key.str()) == std::end(kTopKeys)) {
      problem(toml_line(node), "unknown key '" + echo(key.str()) +
                                   "' (a preset has scene, name, description, [params], "
                                   "[camera], [settings], [[lights]])");
      ok = false;
    }
  if (const toml::node* n = root->get("settings"); n && !n->as_table()) {
    problem(toml_line(*n), "[settings] must be a table of settings by key");
    ok = false;
  }
  Preset p;
  p.id = id;
  p.file = file;
  p.text = text;
  const auto scene = (*root)["scene"].value<std::string>();
  const auto name = (*root)["name"].value<std::string>();
  if (!scene || scene->empty()) {
    problem(0, "needs scene = \"ID\", the scene it is for");
    ok = false;
  }
  if (!name || name->empty()) {
    problem(0, "needs name = \"...\", its display name");
    ok = false;
  }
  if (!ok) return std::nullopt;
  p.scene_id = *scene;
  p.name = *name;
  p.description = (*root)["description"].value<std::string>().value_or("");
  return p;
}

namespace {
constexpr double kNoLow[3] = {0, 0, 0};
}  // namespace

std::string format_preset(const SceneInfo& scene, const SceneState& state, const std::string& name,
                          const std::string& description) {
  std::string out = "scene = " + toml_string_text(scene.id) + "\nname = " +
                    toml_string_text(name) + "\ndescription = " +
                    toml_string_text(description) + "\n\n[params]\n";
  for (size_t i = 0; i < scene.params.size() && i < state.params.size(); ++i)
    out += scene.params[i].key + " = " + toml_param_text(scene.params[i], state.params[i]) + "\n";
  const fr_camera& c = state.camera;
  out += "\n[camera]\neye = " + toml_position_text(c.eye, state.camera_lo.eye) +
         "\ntarget = " + toml_position_text(c.target, state.camera_lo.target) + "\nup = " +
         toml_position_text(c.up, kNoLow) + "\nfov_deg = " + fmt::format("{}", c.fov_deg) +
         "\n";
  return out;
}

std::optional<Preset> read_preset_file(const std::filesystem::path& file, const std::string& id,
                                       std::vector<std::string>* problems) {
  std::ifstream in(file, std::ios::binary);
  std::string text;
  text.resize(kMaxPresetBytes + 1);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (!in.eof() && text.size() > kMaxPresetBytes) {
    problems->push_back(where(file, 0) + "larger than " + std::to_string(kMaxPresetBytes) +
                        " bytes");
    return std::nullopt;
  }
  if (!in.is_open() || in.bad() || (!in.eof() && !in)) {
    problems->push_back(where(file, 0) + "cannot be read");
    return std::nullopt;
  }
  return preset_from_text(text, file, id, problems);
}

std::vector<std::pair<std::string, std::string>> preset_settings(const Preset& preset,
                                                                 std::vector<std::string>* problems) {
  std::vector<std::pair<std::string, std::string>> out;
  auto root = parse(preset.text, preset.file, problems);
  if (!root) return out;
  const toml::table* t = root->get("settings") ? root->get("settings")->as_table() : nullptr;
  if (!t) return out;
  for (const auto& [key, value] : *t) {
    // Only how the picture is rendered: a preset file from elsewhere must not turn plugin
    // isolation off, add plugin folders or change the user's window and keys.
    if (key.str().rfind("render.", 0) != 0) {
      problems->push_back(where(preset.file, toml_line(value)) + "[settings] " +
                          echo(key.str()) + ": a preset sets render.* settings only");
      continue;
    }
    std::string text;
    if (auto b = value.value_exact<bool>()) text = *b ? "true" : "false";
    else if (auto i = value.value_exact<int64_t>()) text = std::to_string(*i);
    else if (auto d = value.value_exact<double>()) {
      std::ostringstream s;
      s.precision(17);
      s << *d;
      text = s.str();
    } else if (auto str = value.value_exact<std::string>()) text = *str;
    else if (const auto v = toml_vec3(value)) {  // a colour
      std::ostringstream s;
      s.precision(17);
      s << "[" << v->x << ", " << v->y << ", " << v->z << "]";
      text = s.str();
    } else {
      problems->push_back(where(preset.file, toml_line(value)) + std::string(key.str()) +
                          ": expected a number, a boolean, a string or [r, g, b]");
      continue;
    }
    out.emplace_back(std::string(key.str()), text);
  }
  return out;
}

std::vector<std::string> apply_preset_settings(const Preset& preset, Settings& settings,
                                               std::vector<std::string>* applied) {
  std::vector<std::string> problems;
  for (const auto& [key, value] : preset_settings(preset, &problems)) {
    const auto wrong = apply_setting_override(key + "=" + value, settings);
    if (!wrong.empty()) {
      problems.push_back(where(preset.file, 0) + "[settings] " + wrong.front().to_string());
      continue;
    }
    if (applied) applied->push_back(key);
  }
  return problems;
}

std::vector<Preset> load_presets(const std::vector<std::filesystem::path>& plugin_folders,
                                 std::vector<PresetProblem>* problems) {
  std::map<std::string, Preset> by_id;
  for (const auto& folder : plugin_folders) {
    const auto dir = folder / "presets";
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
      if (entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      auto problem = [&](int line, const std::string& what) {
        problems->push_back({file, where(file, line) + what});
      };
      const std::string id = file.stem().string();
      if (!is_preset_id(id)) {
        problem(0, "the file name must be the preset's id, [a-z][a-z0-9_-]* (at most 63 bytes)");
        continue;
      }
      if (auto it = by_id.find(id); it != by_id.end()) {
        problem(0, "preset '" + id + "' is already defined by " + it->second.file.string() +
                       "; this one is not used");
        continue;
      }
      std::vector<std::string> file_problems;
      auto p = read_preset_file(file, id, &file_problems);
      for (auto& m : file_problems) problems->push_back({file, std::move(m)});
      if (!p) continue;
      by_id.emplace(id, std::move(*p));
    }
  }
  std::vector<Preset> out;
  for (auto& [id, p] : by_id) out.push_back(std::move(p));
  return out;
}

std::vector<std::string> apply_preset(const Preset& preset, const SceneInfo& scene,
                                      SceneState& state) {
  std::vector<std::string> problems;
  auto root = parse(preset.text, preset.file, &problems);
  if (!root) return problems;
  auto problem = [&](int line, const std::string& what) {
    problems.push_back(where(preset.file, line) + what);
  };
  if (preset.scene_id != scene.id)
    problem(0, "is for scene '" + echo(preset.scene_id) + "', not '" + scene.id + "'");
  SceneState next = state;
  if (const toml::node* n = root->get("params")) {
    const toml::table* t = n->as_table();
    if (!t) {
      problem(toml_line(*n), "[params] must be a table of values by key");
    } else {
      for (const auto& [key, value] : *t) {
        const int index = scene.find_param(std::string(key.str()));
        if (index < 0) {
          problem(toml_line(value), "scene '" + scene.id + "' has no parameter '" +
                                        echo(key.str()) + "'");
          continue;
        }
        std::string why;
        if (auto v = toml_param_value(value, scene.params[index], &why))
          next.params[index] = *v;
        else
          problem(toml_line(value), std::string(key.str()).append(": ").append(why));
      }
    }
  }
  if (const toml::node* n = root->get("camera")) {
    const toml::table* t = n->as_table();
    if (!t) {
      problem(toml_line(*n), "[camera] must be a table (eye, target, up, fov_deg)");
    } else {
      for (const auto& [key, value] : *t) {
        const std::string k(key.str());
        if (std::find(std::begin(kCameraKeys), std::end(kCameraKeys), k) ==
            std::end(kCameraKeys)) {
          problem(toml_line(value), "unknown camera key '" + echo(k) +
                                        "' (eye, target, up, fov_deg)");
          continue;
        }
        if (k == "fov_deg") {
          if (auto f = toml_number(value))
            next.camera.fov_deg = *f;
          else
            problem(toml_line(value), "fov_deg: expected a finite number");
          continue;
        }
        if (k == "up") {
          if (auto v = toml_vec3(value))
            store_dvec3(next.camera.up, *v);
          else
            problem(toml_line(value), "up: expected [x, y, z] (three finite numbers)");
          continue;
        }
        // Positions keep every digit a pair holds (a deep view's, docs/deep_zoom.md).
        const auto v = toml_vec3_pairs(value);
        if (!v) {
          problem(toml_line(value), k + ": expected [x, y, z] (three finite numbers, or decimal "
                                        "strings for more digits than a double holds)");
          continue;
        }
        double* hi = k == "eye" ? next.camera.eye : next.camera.target;
        double* lo = k == "eye" ? next.camera_lo.eye : next.camera_lo.target;
        for (int i = 0; i < 3; ++i) {
          hi[i] = (*v)[i].hi;
          lo[i] = (*v)[i].lo;
        }
      }
      if (auto why = check_camera(next.camera, next.camera_lo))
        problem(toml_line(*n), "camera: " + *why);
    }
  }
  if (const toml::node* n = root->get("lights")) {
    // [[lights]]: lights in place of the scene's first ones, in order.
    const toml::array* lights = n->as_array();
    if (!lights || !lights->is_array_of_tables()) {
      problem(toml_line(*n), std::string("[[lights]] must be tables (") + kLightKeysText + ")");
    } else if (lights->size() > next.lights.size()) {
      problem(toml_line(*n), std::to_string(lights->size()) + " lights, and scene '" + scene.id +
                                 "' has " + std::to_string(next.lights.size()));
    } else {
      for (size_t i = 0; i < lights->size(); ++i) {
        const toml::table& t = *lights->get(i)->as_table();
        fr_light light = next.lights[i];
        if (t.contains("direction") && t.contains("position")) {
          problem(toml_line(t), "a light has a direction or a position, not both");
          continue;
        }
        // Which kind: what the entry gives, else the scene's light's.
        if (t.contains("direction")) {
          light.kind = FR_LIGHT_DIRECTIONAL;
          light.attenuation = 0;
        } else if (t.contains("position")) {
          light.kind = FR_LIGHT_POINT;
        } else if (t.contains("attenuation") || t.contains("falloff")) {
          if (light.kind != FR_LIGHT_POINT)
            problem(toml_line(t), "attenuation and falloff are a point light's (give its position)");
        }
        for (const auto& [key, value] : t) {
          const std::string k(key.str());
          if (std::find(std::begin(kLightKeys), std::end(kLightKeys), k) == std::end(kLightKeys)) {
            problem(toml_line(value),
                    "unknown light key '" + echo(k) + "' (" + kLightKeysText + ")");
            continue;
          }
          if (k == "intensity" || k == "attenuation" || k == "falloff") {
            const bool falloff = k == "falloff";  // (e > 0, as the ABI has it)
            const auto v = toml_number(value);
            // (Intensity and attenuation as a close-up's lights need them: its light falls off
            // over distances of 1e-6 and less. The kernel holds them as floats.)
            if (!v || !(falloff ? *v > 0 && *v <= 4 : *v >= 0 && *v <= 1e30)) {
              problem(toml_line(value), k + (falloff ? ": expected a number above 0, at most 4"
                                                     : ": expected a number from 0 to 1e30"));
              continue;
            }
            (k == "intensity" ? light.intensity : k == "attenuation" ? light.attenuation
                                                                     : light.falloff) = *v;
            continue;
          }
          const auto v = toml_vec3(value);
          const bool ok = v && (k == "color"      ? v->x >= 0 && v->y >= 0 && v->z >= 0
                                : k == "position" ? true
                                                  : v->x != 0 || v->y != 0 || v->z != 0);
          if (!ok) {
            problem(toml_line(value), k + (k == "color"      ? ": expected [r, g, b], none below 0"
                                           : k == "position" ? ": expected [x, y, z]"
                                                             : ": expected [x, y, z], not zero"));
            continue;
          }
          store_dvec3(k == "color" ? light.color : light.vector, *v);
        }
        next.lights[i] = light;
      }
    }
  }
  if (problems.empty()) state = std::move(next);
  return problems;
}

std::optional<Preset> find_preset(const std::vector<Preset>& presets, const std::string& id) {
  for (const Preset& p : presets)
    if (p.id == id) return p;
  return std::nullopt;
}

}  // namespace fr
