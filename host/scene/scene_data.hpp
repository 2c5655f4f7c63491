// scene_data.hpp — a scene as plain data: what it declared (SceneInfo, ParamInfo) and the state
// the host keeps for it (SceneState). No plugin code or process behind it: the renderer, the
// kernel assembler and the sweep work from these alone, and only plugin/ knows how they were
// obtained (plugin/scene_info.hpp adds LoadedScene, which also runs the scene's callbacks).
//
// The loader builds a SceneInfo from the plugin's fr_scene_desc; every string and table is
// copied, so a SceneInfo never points into plugin memory and can cross processes.
#pragma once

#include <fractalis/fractalis.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace fr {

struct ParamInfo {
  std::string key;
  std::string name;
  std::string group;
  std::string description;
  fr_param_type type = FR_PARAM_FLOAT;
  fr_param_flags flags = 0;
  fr_value default_value{};
  fr_value min_value{};
  fr_value max_value{};
  std::vector<std::string> choices;  // FR_PARAM_CHOICE: the names of its values, by index
  // ABI 1.4: an iteration count's detail ratio (fr_param_desc.detail_ratio); 0 for the rest.
  double detail_ratio = 0;

  int component_count() const { return type == FR_PARAM_VEC3 || type == FR_PARAM_COLOR ? 3 : 1; }
  // Whole-number types (int, bool, choice): an int in the kernel, rounded when clamped.
  bool whole() const {
    return type == FR_PARAM_INT || type == FR_PARAM_BOOL || type == FR_PARAM_CHOICE;
  }
  // The name of a choice value (its index clamped into range), or "" for other types.
  std::string choice_name(const fr_value& v) const;
  // The index of a choice's name, or -1.
  int choice_index(const std::string& name) const;
  bool specialized() const { return (flags & FR_PARAM_SPECIALIZE) != 0; }
};

const char* param_type_name(fr_param_type type);

struct SceneInfo;
// The scene's tags as words, in the order it gave them (its family first).
std::vector<std::string> scene_tags(const SceneInfo& info);

// Why a camera cannot make rays (a non-finite value, fov outside (0, 180) degrees, target at the
// eye), or nullopt when it can. An up vector that is zero or parallel to the view is fine: the
// camera then uses a stable perpendicular (camera_up.hpp). Checked on a scene's default
// camera when it loads, and on the camera the command line sets.
std::optional<std::string> check_camera(const fr_camera& camera);

// The camera's eye and target past double (render.precision "dd", docs/deep_zoom.md): what each
// coordinate lacks of the value given, so that eye[i] + eye_lo[i] is the pair (a double-double,
// |lo| at most half an ulp of the double). Zero unless something deeper than double set them: an
// --eye or --target with more digits, a preset or a camera path that has them. The ABI's camera
// (what a scene's callbacks see) stays double; a scene that moves it leaves these as they were,
// which moves the pair by at most half an ulp of the new double.
struct CameraLow {
  double eye[3] = {0, 0, 0};
  double target[3] = {0, 0, 0};
  bool operator==(const CameraLow&) const = default;
};

// check_camera for the pairs: the target may equal the eye in double and still lie apart.
std::optional<std::string> check_camera(const fr_camera& camera, const CameraLow& low);

// target - eye from the pairs, each coordinate rounded once to double: the view's direction and
// length when eye and target are closer than double can tell apart.
std::array<double, 3> view_vector(const fr_camera& camera, const CameraLow& low);

struct SceneInfo {
  std::string id;
  std::string name;
  std::string version;
  std::string author;
  std::string license;
  std::string description;
  std::string tags;    // space-separated words, family first ("" when none); see scene_tags
  std::string credit;  // who found the formula, where published ("" when not given)
  std::string de_source;
  std::string de_source_name;  // for compiler messages; "<id>.cl" when the plugin gave none
  std::string surface_source;  // empty: the host's material settings
  std::string surface_source_name;
  std::vector<ParamInfo> params;
  fr_features features = 0;
  fr_camera camera{};
  std::vector<fr_light> lights;
  double bounding_radius = 0;

  // Index of the parameter with this key, or -1.
  int find_param(const std::string& key) const;
};

// The host-owned state of a scene in use: what its update callback is lent each frame.
struct SceneState {
  std::vector<fr_value> params;  // one per SceneInfo::params, same order
  fr_camera camera{};
  CameraLow camera_lo;  // the eye's and target's digits past double (zero for most views)
  std::vector<fr_light> lights;
  double time_s = 0;
  double dt_s = 0;
  uint64_t frame_index = 0;
  double bounding_radius = 0;
};

}  // namespace fr
