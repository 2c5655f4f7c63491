#include "plugin/scene_checks.hpp"

#include "io/printable.hpp"

#include <cmath>
#include <sstream>
#include <vector>

namespace fr {
namespace {

bool is_identifier(const std::string& s, bool allow_dash) {
  if (s.empty() || s.size() > kMaxIdBytes || !(s[0] >= 'a' && s[0] <= 'z')) return false;
  for (char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || (allow_dash && c == '-')))
      return false;
  return true;
}

std::string describe_value(const fr_value& v, int n) {
  std::ostringstream out;
  for (int i = 0; i < n; ++i) out << (i ? "," : "") << v.v[i];
  return out.str();
}

// Why a string field is not acceptable text within its cap, or nullopt.
std::optional<std::string> check_text(const char* field, const std::string& text, size_t cap,
                                      bool multiline) {
  if (text.size() > cap)
    return std::string(field) + " is " + std::to_string(text.size()) + " bytes, more than " +
           std::to_string(cap);
  if (std::string problem = utf8_text_problem(text, multiline); !problem.empty())
    return std::string(field) + " is not clean text: " + problem;
  return std::nullopt;
}

// Tags: space-separated words [a-z0-9][a-z0-9-]*, at most kMaxSceneTags, none twice.
std::optional<std::string> check_tags(const std::string& tags) {
  std::vector<std::string> seen;
  size_t i = 0;
  while (i < tags.size()) {
    if (tags[i] == ' ') {
      ++i;
      continue;
    }
    size_t end = tags.find(' ', i);
    if (end == std::string::npos) end = tags.size();
    const std::string word = tags.substr(i, end - i);
    const bool first_ok = (word[0] >= 'a' && word[0] <= 'z') || (word[0] >= '0' && word[0] <= '9');
    bool rest_ok = true;
    for (char c : word)
      rest_ok = rest_ok && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-');
    if (!first_ok || !rest_ok)
      return "tag '" + printable(word) +
             "' must match [a-z0-9][a-z0-9-]* (tags are separated by spaces)";
    for (const std::string& s : seen)
      if (s == word) return "tag '" + word + "' appears twice";
    seen.push_back(word);
    if (seen.size() > kMaxSceneTags) return "more than " + std::to_string(kMaxSceneTags) + " tags";
    i = end;
  }
  return std::nullopt;
}

bool finite3(const double* v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

std::optional<std::string> check_light(const fr_light& light) {
  if (light.kind != FR_LIGHT_DIRECTIONAL && light.kind != FR_LIGHT_POINT)
    return "kind " + std::to_string(light.kind) + " is neither directional (1) nor point (2)";
  if (!finite3(light.vector) || !finite3(light.color) || !std::isfinite(light.intensity))
    return "has a non-finite vector, colour or intensity";
  if (light.kind == FR_LIGHT_DIRECTIONAL && light.vector[0] == 0 && light.vector[1] == 0 &&
      light.vector[2] == 0)
    return "is directional with a zero direction";
  if (!(light.attenuation >= 0) || !std::isfinite(light.attenuation) ||
      (light.attenuation > 0 && !(light.falloff > 0 && std::isfinite(light.falloff))))
    return "needs attenuation >= 0 and, when attenuation > 0, falloff > 0";
  if (!(light.radius >= 0) || !std::isfinite(light.radius))
    return "has radius " + std::to_string(light.radius) + " (needs a finite radius >= 0)";
  if (light.kind == FR_LIGHT_DIRECTIONAL && !(light.radius < 0.5))
    return "is directional with an angular radius of " + std::to_string(light.radius) +
           " radians (needs below 0.5)";
  return std::nullopt;
}

std::optional<std::string> check_param_info(const ParamInfo& p, size_t index) {
  const std::string where =
      "parameter " + std::to_string(index) + (p.key.empty() ? "" : " '" + printable(p.key) + "'");
  if (!is_identifier(p.key, false))
    return where + ": key must match [a-z][a-z0-9_]* (at most 63 bytes)";
  if (p.name.empty()) return where + ": name is empty";
  if (auto e = check_text("name", p.name, kMaxLabelBytes, false)) return where + ": " + *e;
  if (auto e = check_text("group", p.group, kMaxLabelBytes, false)) return where + ": " + *e;
  if (auto e = check_text("description", p.description, kMaxDescriptionBytes, false))
    return where + ": " + *e;
  if (p.type < FR_PARAM_FLOAT || p.type > FR_PARAM_CHOICE)
    return where + ": type " + std::to_string(p.type) +
           " is not one of float, int, bool, vec3, color, choice";
  if (p.flags & ~fr_param_flags{FR_PARAM_ANIMATABLE | FR_PARAM_SPECIALIZE | FR_PARAM_LOG_SCALE})
    return where + ": unknown flag bits " + std::to_string(p.flags);
  if ((p.flags & FR_PARAM_SPECIALIZE) && (p.flags & FR_PARAM_ANIMATABLE))
    return where + ": cannot be both SPECIALIZE and ANIMATABLE";
  const int n = p.component_count();
  for (int i = 0; i < n; ++i) {
    const double lo = p.min_value.v[i], def = p.default_value.v[i], hi = p.max_value.v[i];
    if (!std::isfinite(lo) || !std::isfinite(def) || !std::isfinite(hi) ||
        !(lo <= def && def <= hi))
      return where + ": needs finite min <= default <= max, got min " +
             describe_value(p.min_value, n) + ", default " + describe_value(p.default_value, n) +
             ", max " + describe_value(p.max_value, n);
    if (p.whole() && (lo != std::floor(lo) || def != std::floor(def) || hi != std::floor(hi)))
      return where + ": int, bool and choice limits must be whole numbers";
    if (p.type == FR_PARAM_INT && (lo < -2147483648.0 || hi > 2147483647.0))
      return where + ": int limits must fit in 32 bits";
  }
  if (p.type == FR_PARAM_BOOL && (p.min_value.v[0] != 0 || p.max_value.v[0] != 1))
    return where + ": a bool's min must be 0 and max 1";
  if ((p.flags & FR_PARAM_LOG_SCALE) && !(p.min_value.v[0] > 0))
    return where + ": LOG_SCALE needs min > 0";
  if (p.type == FR_PARAM_CHOICE) {
    if (p.choices.empty() || p.choices.size() > kMaxChoices)
      return where + ": a choice needs 1 to " + std::to_string(kMaxChoices) + " names";
    for (size_t c = 0; c < p.choices.size(); ++c) {
      if (!is_identifier(p.choices[c], false))
        return where + ": choice name '" + printable(p.choices[c]) +
               "' must match [a-z][a-z0-9_]* (at most 63 bytes)";
      for (size_t d = 0; d < c; ++d)
        if (p.choices[d] == p.choices[c])
          return where + ": choice name '" + p.choices[c] + "' appears twice";
    }
    if (p.min_value.v[0] != 0 || p.max_value.v[0] != static_cast<double>(p.choices.size() - 1))
      return where + ": a choice's min must be 0 and max its number of names minus 1 (" +
             std::to_string(p.choices.size() - 1) + ")";
    if (p.flags & FR_PARAM_LOG_SCALE) return where + ": a choice cannot be LOG_SCALE";
  } else if (!p.choices.empty()) {
    return where + ": only a choice has names";
  }
  if (p.detail_ratio != 0) {
    if (p.type != FR_PARAM_INT)
      return where + ": only an int iteration count has a detail_ratio";
    if (!(p.detail_ratio > 1) || !std::isfinite(p.detail_ratio) || p.detail_ratio > 1e6)
      return where + ": detail_ratio " + describe_value(fr_value{{p.detail_ratio, 0, 0}}, 1) +
             " must be above 1 and finite (or 0: not an iteration count)";
  }
  return std::nullopt;
}

std::optional<std::string> check_scene_info(const SceneInfo& info) {
  if (!is_identifier(info.id, true))
    return "scene id '" + printable(info.id) + "' must match [a-z][a-z0-9_-]* (at most 63 bytes)";
  const std::string scene = "scene '" + info.id + "': ";
  if (info.name.empty()) return scene + "name is empty";
  if (info.version.empty()) return scene + "version is empty";
  const struct {
    const char* field;
    const std::string& text;
    size_t cap;
    bool multiline;
  } texts[] = {{"name", info.name, kMaxLabelBytes, false},
               {"version", info.version, kMaxLabelBytes, false},
               {"author", info.author, kMaxLabelBytes, false},
               {"license", info.license, kMaxLabelBytes, false},
               {"description", info.description, kMaxDescriptionBytes, false},
               {"tags", info.tags, kMaxLabelBytes, false},
               {"credit", info.credit, kMaxLabelBytes, false},
               {"de_source", info.de_source, kMaxSourceBytes, true},
               {"de_source_name", info.de_source_name, kMaxLabelBytes, false},
               {"surface_source", info.surface_source, kMaxSourceBytes, true},
               {"surface_source_name", info.surface_source_name, kMaxLabelBytes, false}};
  for (const auto& t : texts)
    if (auto e = check_text(t.field, t.text, t.cap, t.multiline)) return scene + *e;
  if (auto e = check_tags(info.tags)) return scene + *e;
  if (info.de_source.empty())
    return scene + "de_source is empty (expected OpenCL C defining scene_de)";
  if (!(info.bounding_radius > 0 && std::isfinite(info.bounding_radius)))
    return scene + "bounding_radius must be finite and > 0";
  if (info.features & ~fr_features{FR_FEATURE_SHADOWS | FR_FEATURE_AO | FR_FEATURE_GLOW |
                                   FR_FEATURE_FOG | FR_FEATURE_REFLECTIONS})
    return scene + "unknown feature bits in " + std::to_string(info.features);
  if (info.params.size() > kMaxSceneParams)
    return scene + std::to_string(info.params.size()) + " parameters, more than " +
           std::to_string(kMaxSceneParams);
  for (size_t i = 0; i < info.params.size(); ++i) {
    if (auto e = check_param_info(info.params[i], i)) return scene + *e;
    for (size_t j = 0; j < i; ++j)
      if (info.params[j].key == info.params[i].key)
        return scene + "parameter key '" + info.params[i].key + "' appears twice";
  }
  if (auto problem = check_camera(info.camera)) return scene + "default camera: " + *problem;
  if (info.lights.size() > FR_MAX_SCENE_LIGHTS)
    return scene + std::to_string(info.lights.size()) + " lights, more than FR_MAX_SCENE_LIGHTS (" +
           std::to_string(FR_MAX_SCENE_LIGHTS) + ")";
  for (size_t i = 0; i < info.lights.size(); ++i)
    if (auto e = check_light(info.lights[i]))
      return scene + "light " + std::to_string(i) + " " + *e;
  return std::nullopt;
}

}  // namespace fr
