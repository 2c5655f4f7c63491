// scene_info.hpp — a loaded scene: its plain data (scene/scene_data.hpp) and the code that runs
// its callbacks.
#pragma once

#include "scene/scene_data.hpp"

#include <filesystem>
#include <memory>

namespace fr {

class SceneCode;

// A scene that loaded: the host's copy of its descriptor, and what runs its callbacks (in a
// scene-host process by default; see scene_code.hpp).
struct LoadedScene {
  SceneInfo info;
  std::filesystem::path file;  // the plugin as found in the folder (not the private copy)
  std::shared_ptr<SceneCode> code;
};

}  // namespace fr
