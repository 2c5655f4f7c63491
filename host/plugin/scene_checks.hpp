// scene_checks.hpp — every rule a scene's descriptor must keep, checked on the host's copy.
//
// The loader runs these in the scene-host process right after copying the descriptor (so the
// plugin's author gets the message), and the host runs them again on what it receives (the
// scene-host process runs plugin code, so its answer is not trusted either).
#pragma once

#include "plugin/scene_info.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace fr {

// Caps on what a descriptor may hold; the header (scene.h, param.h) promises these.
constexpr size_t kMaxIdBytes = 63;             // scene ids and parameter keys
constexpr size_t kMaxLabelBytes = 256;         // names, versions, authors, licences, groups
constexpr size_t kMaxDescriptionBytes = 4096;  // descriptions
constexpr size_t kMaxSourceBytes = 1 << 20;    // OpenCL sources
constexpr uint32_t kMaxSceneParams = 256;
constexpr size_t kMaxSceneTags = 16;
constexpr uint32_t kMaxChoices = 64;  // values of one choice parameter

// Why `info` breaks a rule ("parameter 2 'scale': needs finite min <= default <= max ..."), or
// nullopt when it keeps them all. Messages start with "scene '<id>': " once the id is known.
std::optional<std::string> check_scene_info(const SceneInfo& info);

// Why a light cannot be used (unknown kind, non-finite value, negative attenuation), or nullopt.
std::optional<std::string> check_light(const fr_light& light);

// Why one parameter description is wrong, or nullopt. `index` is for the message.
std::optional<std::string> check_param_info(const ParamInfo& p, size_t index);

}  // namespace fr
