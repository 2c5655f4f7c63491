#include "scene/scene_data.hpp"

#include "scene/camera_up.hpp"
#include "scene/vec3.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace fr {

const char* param_type_name(fr_param_type type) {
  switch (type) {
    case FR_PARAM_FLOAT:
      return "float";
    case FR_PARAM_INT:
      return "int";
    case FR_PARAM_BOOL:
      return "bool";
    case FR_PARAM_VEC3:
      return "vec3";
    case FR_PARAM_COLOR:
      return "color";
    case FR_PARAM_CHOICE:
      return "choice";
  }
  return "unknown";
}

std::vector<std::string> scene_tags(const SceneInfo& info) {
  std::vector<std::string> words;
  std::string word;
  for (char c : info.tags + ' ') {
    if (c != ' ') {
      word += c;
    } else if (!word.empty()) {
      words.push_back(word);
      word.clear();
    }
  }
  return words;
}

std::string ParamInfo::choice_name(const fr_value& v) const {
  if (type != FR_PARAM_CHOICE || choices.empty()) return "";
  const double i = std::clamp(std::round(v.v[0]), 0.0, static_cast<double>(choices.size() - 1));
  return choices[static_cast<size_t>(i)];
}

int ParamInfo::choice_index(const std::string& name) const {
  for (size_t i = 0; i < choices.size(); ++i)
    if (choices[i] == name) return static_cast<int>(i);
  return -1;
}

int SceneInfo::find_param(const std::string& key) const {
  for (size_t i = 0; i < params.size(); ++i)
    if (params[i].key == key) return static_cast<int>(i);
  return -1;
}

std::optional<std::string> check_camera(const fr_camera& c) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c.eye[i]) || !std::isfinite(c.target[i]) || !std::isfinite(c.up[i]))
      return "camera has a non-finite coordinate";
  if (!(c.fov_deg > 0 && c.fov_deg < 180))
    return "field of view " + std::to_string(c.fov_deg) + " is outside (0, 180) degrees";
  const glm::dvec3 t = to_dvec3(c.target) - to_dvec3(c.eye);
  if (glm::length(t) == 0) return "target equals eye";
  // An up that is zero or parallel to the view is fine: effective_up takes a perpendicular.
  return std::nullopt;
}

std::array<double, 3> view_vector(const fr_camera& c, const CameraLow& low) {
  std::array<double, 3> v{};
  for (int i = 0; i < 3; ++i) {
    // Knuth's TwoSum: s + e is target.hi - eye.hi exactly; the low parts are far smaller.
    const double a = c.target[i], b = -c.eye[i];
    const double s = a + b, bb = s - a;
    const double e = (a - (s - bb)) + (b - bb);
    v[i] = s + (e + (low.target[i] - low.eye[i]));
  }
  return v;
}

std::optional<std::string> check_camera(const fr_camera& c, const CameraLow& low) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(low.eye[i]) || !std::isfinite(low.target[i]))
      return "camera has a non-finite coordinate";
  fr_camera relative = c;
  const std::array<double, 3> v = view_vector(c, low);
  for (int i = 0; i < 3; ++i) {
    relative.eye[i] = 0;
    relative.target[i] = v[i];
  }
  if (auto problem = check_camera(c); problem && *problem != "target equals eye") return problem;
  return check_camera(relative);
}

glm::dvec3 effective_up(const fr_camera& c) {
  const glm::dvec3 t = glm::normalize(to_dvec3(c.target) - to_dvec3(c.eye));
  const glm::dvec3 up = to_dvec3(c.up);
  const double up_length = glm::length(up);
  if (up_length > 0 && glm::length(glm::cross(up / up_length, t)) > 1e-6) return up;
  // The world axis least aligned with the view; y, then z, then x on ties.
  const glm::dvec3 axes[] = {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
  glm::dvec3 best = axes[0];
  for (const glm::dvec3& a : axes)
    if (std::abs(glm::dot(a, t)) < std::abs(glm::dot(best, t)) - 1e-12) best = a;
  return best;
}

}  // namespace fr
