// scene_info.hpp — the host's own copy of everything a scene plugin declared.
//
// Built by the loader from the plugin's fr_scene_desc; every string and table is copied, so a
// SceneInfo never points into plugin memory. Only the callbacks do, which is why a LoadedScene
// keeps its library mapped for as long as it lives.
#pragma once

#include <fractalis/fractalis.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fr {

class PluginLibrary;

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

  int component_count() const { return type == FR_PARAM_VEC3 || type == FR_PARAM_COLOR ? 3 : 1; }
  bool specialized() const { return (flags & FR_PARAM_SPECIALIZE) != 0; }
};

const char* param_type_name(fr_param_type type);

// Why a camera cannot make rays (a non-finite value, fov outside (0, 180) degrees, target at the
// eye, up zero or parallel to the view), or nullopt when it can. Checked on a scene's default
// camera when it loads, and on the camera the command line sets.
std::optional<std::string> check_camera(const fr_camera& camera);

struct SceneInfo {
  std::string id;
  std::string name;
  std::string version;
  std::string author;
  std::string license;
  std::string description;
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

// A scene whose library is loaded. The callbacks point into the library, which stays mapped
// while any LoadedScene (or an instance made from it) holds it.
struct LoadedScene {
  SceneInfo info;
  std::filesystem::path file;  // the plugin as found in the folder (not the private copy)
  fr_create_fn create = nullptr;
  fr_destroy_fn destroy = nullptr;
  fr_update_fn update = nullptr;
  std::shared_ptr<PluginLibrary> library;
};

}  // namespace fr
