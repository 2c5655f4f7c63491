#include "path/camera_path.hpp"

#include "path/toml_values.hpp"

#include "io/echo.hpp"
#include "io/toml_guard.hpp"
#include "scene/camera_up.hpp"
#include "scene/vec3.hpp"

#include <spdlog/fmt/fmt.h>
#include <toml++/toml.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace fr {
namespace {

const char* const kKeyframeKeys[] = {"time_s", "eye", "target", "up", "fov_deg", "params"};

// target - eye from the pairs (scene_data.hpp's view_vector).
glm::dvec3 view_of(const Keyframe& k) {
  fr_camera c{};
  CameraLow low;
  store_dvec3(c.eye, k.eye);
  store_dvec3(c.target, k.target);
  store_dvec3(low.eye, k.eye_lo);
  store_dvec3(low.target, k.target_lo);
  const std::array<double, 3> v = view_vector(c, low);
  return {v[0], v[1], v[2]};
}

// The keyframe's orientation: right, up and back (-forward) as the rotation's columns.
glm::dquat orientation(const Keyframe& k) {
  fr_camera c{};
  store_dvec3(c.eye, k.eye);
  store_dvec3(c.target, k.target);
  store_dvec3(c.up, k.up);
  const glm::dvec3 forward = glm::normalize(view_of(k));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, effective_up(c)));
  const glm::dvec3 up = glm::cross(right, forward);
  return glm::quat_cast(glm::dmat3(right, up, -forward));
}

// The centripetal Catmull-Rom segment from p1 to p2 at u in [0, 1] (Barry and Goldman's
// pyramid, knot intervals the square roots of the chord lengths).
glm::dvec3 catmull_rom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2,
                       const glm::dvec3& p3, double u) {
  auto interval = [](const glm::dvec3& a, const glm::dvec3& b) {
    const double d = std::sqrt(glm::length(b - a));
    return d > 1e-12 ? d : 1.0;  // coincident points: any interval gives the same point
  };
  if (glm::length(p2 - p1) == 0) return p1;
  const double t0 = 0, t1 = t0 + interval(p0, p1), t2 = t1 + interval(p1, p2),
               t3 = t2 + interval(p2, p3);
  const double t = t1 + u * (t2 - t1);
  auto lerp = [&](const glm::dvec3& a, const glm::dvec3& b, double ta, double tb) {
    return ((tb - t) * a + (t - ta) * b) / (tb - ta);
  };
  const glm::dvec3 a1 = lerp(p0, p1, t0, t1), a2 = lerp(p1, p2, t1, t2), a3 = lerp(p2, p3, t2, t3);
  const glm::dvec3 b1 = lerp(a1, a2, t0, t2), b2 = lerp(a2, a3, t1, t3);
  return lerp(b1, b2, t1, t2);
}

}  // namespace

std::string PathProblem::to_string() const {
  std::string out = file;  // appended, not "a" + b: GCC 12's -Wrestrict misfires on that
  if (line > 0) out.append(":").append(std::to_string(line));
  return out.append(": ").append(message);
}

std::optional<CameraPath> parse_camera_path(const std::string& text, const std::string& file,
                                            const SceneInfo& scene,
                                            std::vector<PathProblem>* problems) {
  const size_t problems_before = problems->size();
  auto problem = [&](int line, const std::string& message) {
    problems->push_back({file, line, message});
  };
  int deep_line = 0;
  if (std::string why = toml_nesting_problem(text, &deep_line); !why.empty()) {
    problem(deep_line, why);
    return std::nullopt;
  }
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    problem(static_cast<int>(e.source().begin.line),
            "not valid TOML: " + std::string(e.description()));
    return std::nullopt;
  }
  for (const auto& [key, node] : root)
    if (key.str() != "keyframe")
      problem(toml_line(node),
              "unknown key '" + echo(key.str()) + "' (a path holds [[keyframe]] tables only)");
  const toml::array* keys = root["keyframe"].as_array();
  if (!keys || !keys->is_array_of_tables()) {
    problem(keys ? toml_line(*keys) : 0, "expected [[keyframe]] tables");
    return std::nullopt;
  }
  CameraPath path;
  path.file = file;
  Keyframe previous;  // what a keyframe leaves out: the scene's camera and parameters at first
  previous.eye = to_dvec3(scene.camera.eye);
  previous.up = to_dvec3(scene.camera.up);
  previous.fov_deg = scene.camera.fov_deg;
  for (const ParamInfo& p : scene.params) previous.params.push_back(p.default_value);
  for (const toml::node& node : *keys) {
    const toml::table& t = *node.as_table();
    Keyframe k = previous;
    k.line = toml_line(node);
    const std::string where = "keyframe " + std::to_string(path.keyframes.size() + 1) + ": ";
    for (const auto& [key, value] : t)
      if (std::find(std::begin(kKeyframeKeys), std::end(kKeyframeKeys), key.str()) ==
          std::end(kKeyframeKeys))
        problem(toml_line(value), where + "unknown key '" + echo(key.str()) +
                                    "' (expected time_s, eye, target, up, fov_deg, params)");
    auto need_vec3 = [&](const char* name, glm::dvec3* out, bool required) {
      const toml::node* n = t.get(name);
      if (!n) {
        if (required) problem(k.line, where + "'" + name + "' is missing");
        return;
      }
      if (auto v = toml_vec3(*n))
        *out = *v;
      else
        problem(toml_line(*n), where + "'" + name + "': expected [x, y, z] (three finite numbers)");
    };
    // Positions keep every digit a pair holds (a deep zoom's keyframes).
    auto need_position = [&](const char* name, glm::dvec3* hi, glm::dvec3* lo) {
      const toml::node* n = t.get(name);
      if (!n) {
        problem(k.line, where + "'" + name + "' is missing");
        return;
      }
      if (auto v = toml_vec3_pairs(*n)) {
        for (int c = 0; c < 3; ++c) {
          (*hi)[c] = (*v)[c].hi;
          (*lo)[c] = (*v)[c].lo;
        }
      } else {
        problem(toml_line(*n), where + "'" + name +
                                   "': expected [x, y, z] (three finite numbers, or decimal "
                                   "strings for more digits than a double holds)");
      }
    };
    int time_line = k.line;
    if (const toml::node* n = t.get("time_s")) {
      time_line = toml_line(*n);
      if (auto v = toml_number(*n))
        k.time_s = *v;
      else
        problem(toml_line(*n), where + "'time_s': expected a finite number of seconds");
    } else {
      problem(k.line, where + "'time_s' is missing");
    }
    need_position("eye", &k.eye, &k.eye_lo);
    need_position("target", &k.target, &k.target_lo);
    need_vec3("up", &k.up, false);
    if (glm::length(k.up) == 0) problem(k.line, where + "'up' is [0, 0, 0]: it has no direction");
    if (const toml::node* n = t.get("fov_deg")) {
      auto v = toml_number(*n);
      if (!v || !(*v > 0 && *v < 180))
        problem(toml_line(*n), where + "'fov_deg': expected degrees in (0, 180)");
      else
        k.fov_deg = *v;
    }
    if (k.eye == k.target && k.eye_lo == k.target_lo)
      problem(k.line, where + "'target' equals 'eye'");
    if (const toml::node* n = t.get("params")) {
      if (const toml::table* params = n->as_table()) {
        for (const auto& [key, value] : *params) {
          const int index = scene.find_param(std::string(key.str()));
          if (index < 0) {
            problem(toml_line(value),
                    where + "scene '" + scene.id + "' has no parameter '" + echo(key.str()) + "'");
            continue;
          }
          std::string why;
          if (auto v = toml_param_value(value, scene.params[index], &why))
            k.params[index] = *v;
          else
            problem(toml_line(value), where + "parameter '" + scene.params[index].key + "': " + why);
        }
      } else {
        problem(toml_line(*n), where + "'params': expected a table of key = value");
      }
    }
    if (!path.keyframes.empty() && !(k.time_s > path.keyframes.back().time_s))
      problem(time_line, where + fmt::format("time_s {} is not after the previous keyframe's {} "
                                             "(times must increase)",
                                             k.time_s, path.keyframes.back().time_s));
    path.keyframes.push_back(k);
    previous = k;
  }
  if (path.keyframes.size() < 2)
    problem(path.keyframes.empty() ? 0 : path.keyframes.front().line,
            "a path needs at least two keyframes (it has " + std::to_string(path.keyframes.size()) +
                ")");
  if (problems->size() > problems_before) {
    std::stable_sort(problems->begin() + static_cast<std::ptrdiff_t>(problems_before),
                     problems->end(),
                     [](const PathProblem& a, const PathProblem& b) { return a.line < b.line; });
    return std::nullopt;
  }
  return path;
}

std::optional<CameraPath> load_camera_path(const std::filesystem::path& file,
                                           const SceneInfo& scene,
                                           std::vector<PathProblem>* problems) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    problems->push_back({file.string(), 0, "not a readable file"});
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return parse_camera_path(text.str(), file.string(), scene, problems);
}

std::string format_camera_path(const CameraPath& path, const SceneInfo& scene) {
  std::string out =
      fmt::format("# Camera path for scene '{}' (fractalis animate --scene {} --path FILE).\n",
                  scene.id, scene.id);
  auto vec = [](const glm::dvec3& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); };
  auto position = [&](const glm::dvec3& hi, const glm::dvec3& lo) {
    const double h[3] = {hi.x, hi.y, hi.z}, l[3] = {lo.x, lo.y, lo.z};
    return toml_position_text(h, l);
  };
  for (size_t k = 0; k < path.keyframes.size(); ++k) {
    const Keyframe& key = path.keyframes[k];
    out +=
        fmt::format("\n[[keyframe]]\ntime_s = {}\neye = {}\ntarget = {}\nup = {}\nfov_deg = {}\n",
                    key.time_s, position(key.eye, key.eye_lo), position(key.target, key.target_lo),
                    vec(key.up), key.fov_deg);
    std::string params;
    for (size_t i = 0; i < scene.params.size() && i < key.params.size(); ++i) {
      const fr_value& v = key.params[i];
      if (k > 0 && std::memcmp(&v, &path.keyframes[k - 1].params[i], sizeof v) == 0) continue;
      params += scene.params[i].key + " = " + toml_param_text(scene.params[i], v) + "\n";
    }
    if (!params.empty()) out += "[keyframe.params]\n" + params;
  }
  return out;
}

PathSample sample_camera_path(const CameraPath& path, const SceneInfo& scene, double time_s) {
  const auto& keys = path.keyframes;
  const double t = std::clamp(time_s, path.start_s(), path.end_s());
  // The segment [i, i + 1] holding t, and where in it.
  size_t i = 0;
  while (i + 2 < keys.size() && t >= keys[i + 1].time_s) ++i;
  const Keyframe &k1 = keys[i], &k2 = keys[i + 1];
  const double u = std::clamp((t - k1.time_s) / (k2.time_s - k1.time_s), 0.0, 1.0);
  // The neighbours of the end segments: on a closed loop (the last eye is the first), the keys
  // across the seam, so the loop has no kink there; otherwise phantom points, the first and last
  // keys mirrored through their neighbours.
  const size_t n = keys.size();
  const bool closed = n > 2 && keys.front().eye == keys.back().eye;
  const glm::dvec3 p0 = i > 0 ? keys[i - 1].eye : closed ? keys[n - 2].eye : 2.0 * k1.eye - k2.eye;
  const glm::dvec3 p3 = i + 2 < n ? keys[i + 2].eye : closed ? keys[1].eye : 2.0 * k2.eye - k1.eye;
  const glm::dvec3 eye = u == 0 ? k1.eye : u == 1 ? k2.eye : catmull_rom(p0, k1.eye, k2.eye, p3, u);

  glm::dquat q1 = orientation(k1), q2 = orientation(k2);
  if (glm::dot(q1, q2) < 0) q2 = -q2;  // the shorter way round
  const glm::dmat3 r = glm::mat3_cast(glm::normalize(glm::slerp(q1, q2, u)));
  const glm::dvec3 forward = -r[2], up = r[1];
  const double d1 = glm::length(view_of(k1)), d2 = glm::length(view_of(k2));
  const glm::dvec3 target = u == 0   ? k1.target
                            : u == 1 ? k2.target
                                     : eye + forward * ((1 - u) * d1 + u * d2);

  PathSample s;
  s.camera.struct_size = sizeof(fr_camera);
  store_dvec3(s.camera.eye, eye);
  store_dvec3(s.camera.target, target);
  if (u == 0 || u == 1) {
    const Keyframe& k = u == 0 ? k1 : k2;
    store_dvec3(s.camera_lo.eye, k.eye_lo);
    store_dvec3(s.camera_lo.target, k.target_lo);
  } else if (k1.target == k2.target && k1.target_lo == k2.target_lo &&
             std::max(d1, d2) > 2 * std::min(d1, d2)) {
    // A zoom: towards the common target along the view, the distance in log, the eye in pairs.
    const double d = std::exp((1 - u) * std::log(d1) + u * std::log(d2));
    for (int c = 0; c < 3; ++c) {
      const DoubleDouble eye = pair_plus({k1.target[c], k1.target_lo[c]}, -forward[c] * d);
      s.camera.eye[c] = eye.hi;
      s.camera_lo.eye[c] = eye.lo;
      s.camera.target[c] = k1.target[c];
      s.camera_lo.target[c] = k1.target_lo[c];
    }
  }
  // At the keyframes themselves, their own up (the quaternion's is the orthogonalised one).
  store_dvec3(s.camera.up, u == 0 ? k1.up : u == 1 ? k2.up : up);
  s.camera.fov_deg = (1 - u) * k1.fov_deg + u * k2.fov_deg;
  s.params.resize(scene.params.size());
  for (size_t p = 0; p < scene.params.size(); ++p) {
    const ParamInfo& info = scene.params[p];
    for (int c = 0; c < 3; ++c) {
      const double a = k1.params[p].v[c], b = k2.params[p].v[c];
      double v = (1 - u) * a + u * b;
      if (info.type == FR_PARAM_INT) v = std::round(v);
      // A bool or a choice switches at the next keyframe: there is nothing between two names.
      if (info.type == FR_PARAM_BOOL || info.type == FR_PARAM_CHOICE) v = u < 1 ? a : b;
      s.params[p].v[c] = v;
    }
  }
  return s;
}

}  // namespace fr
