// camera_path.hpp — a camera path: keyframes from a TOML file, and the camera and scene
// parameters at any time between them.
//
//   [[keyframe]]
//   time_s = 0.0
//   eye = [3.4, -4.4, 1.5]
//   target = [0.0, 0.0, 0.0]
//   up = [0.0, 0.0, 1.0]        # optional: the previous keyframe's, else the scene's
//   fov_deg = 45.0              # optional: likewise
//   [keyframe.params]           # optional: scene parameters by key
//   power = 8.0
//
// At least two keyframes, times finite and strictly increasing. A parameter a keyframe leaves out
// keeps the value the previous keyframe gave it (the scene's default before the first). Every
// problem is reported as FILE:LINE: what, like the settings file.
//
// Between keyframes: the eye on a centripetal Catmull-Rom spline through the keyframes' eyes
// (alpha = 1/2: no cusps or self-intersections within a segment, and no overshoot of collinear
// keys; Yuksel et al. 2011; a path whose last eye equals its first is a closed loop, smooth across
// the seam), the orientation by spherical interpolation of the keyframes'
// orientation quaternions, the distance to the target, the field of view and the parameters
// linearly (integer parameters rounded, booleans switching at the next keyframe).
//
// A zoom: where two neighbouring keyframes look at the same point (their targets equal, as pairs)
// from distances that differ by more than a factor of two, the eye between them moves along the
// interpolated view direction towards that point, the distance interpolated in log (a constant
// rate of zoom: a path from 1 to 1e-20 spends as long on each factor of ten), and in pairs, so a
// zoom goes past what double holds (docs/deep_zoom.md).
#pragma once

#include "scene/scene_data.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fr {

struct Keyframe {
  double time_s = 0;
  glm::dvec3 eye{0.0}, target{0.0}, up{0.0, 1.0, 0.0};
  // The eye's and target's digits past double (as SceneState::camera_lo): a deep view's keyframe
  // gives them as decimal strings (toml_values.hpp, toml_vec3_pairs).
  glm::dvec3 eye_lo{0.0}, target_lo{0.0};
  double fov_deg = 45;
  std::vector<fr_value> params;  // one per SceneInfo::params, resolved as described above
  int line = 0;                  // of its [[keyframe]] header
};

struct CameraPath {
  std::string file;
  std::vector<Keyframe> keyframes;
  double start_s() const { return keyframes.front().time_s; }
  double end_s() const { return keyframes.back().time_s; }
};

struct PathProblem {
  std::string file;
  int line = 0;
  std::string message;
  std::string to_string() const;  // "FILE:LINE: message"
};

// Parses and checks a path for `scene` (its parameters, and its default camera for what the
// first keyframe leaves out). Returns nullopt with the problems (one or more) when it is not a
// usable path.
std::optional<CameraPath> parse_camera_path(const std::string& text, const std::string& file,
                                            const SceneInfo& scene,
                                            std::vector<PathProblem>* problems);
std::optional<CameraPath> load_camera_path(const std::filesystem::path& file,
                                           const SceneInfo& scene,
                                           std::vector<PathProblem>* problems);

// The path as a TOML file that parse_camera_path reads back to the same keyframes: every
// keyframe with its time, eye, target, up and fov; the first with every parameter, later ones with
// the parameters that changed. Numbers are written in the shortest form that reads back exactly.
std::string format_camera_path(const CameraPath& path, const SceneInfo& scene);

struct PathSample {
  fr_camera camera{};
  CameraLow camera_lo;  // the digits past double of the eye and target
  std::vector<fr_value> params;
};

// The camera and parameters at `time_s`, clamped to the path's first and last keyframes.
PathSample sample_camera_path(const CameraPath& path, const SceneInfo& scene, double time_s);

}  // namespace fr
