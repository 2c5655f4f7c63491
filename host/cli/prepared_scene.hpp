// prepared_scene.hpp — everything a command that renders one scene needs, set up from its
// options: settings, the scene and its instance (vetted in a child process), overrides, camera
// path, device, and whether the image fits in memory.
#pragma once

#include "cli/scene_options.hpp"
#include "path/camera_path.hpp"
#include "worker/render_worker.hpp"

namespace fr {

// Everything a rendering command needs, set up from its options.
struct PreparedScene {
  Settings settings;
  std::shared_ptr<const LoadedScene> scene;
  std::unique_ptr<SceneInstance> instance;
  SceneState state;
  RenderSettings render;
  DeviceInfo device;
  // Renders on `device` in a render worker process (started on first use), each sample within
  // render.watchdog_s.
  std::unique_ptr<RenderWorker> worker;
  std::optional<Preset> preset;  // --preset, applied again wherever the overrides are
};

// Settings, plugins (failures logged as warnings), scene (--scene, default mandelbulb), overrides,
// device, and the scene's instance. Throws UsageError for bad input, runtime_error when the
// scene's create callback fails.
PreparedScene prepare_scene(const ParsedOptions& options, int max_side = kMaxImageSide);

// Runs the scene's update callback at `time_s` on p.state; a failure (the plugin's error, or its
// scene host's crash or time-out) is a std::runtime_error, the one error channel of the commands
// (cli.cpp prints it and exits 1).
void update_scene(PreparedScene& p, double time_s);

// The camera path `file` for scene `info`, or a UsageError "--path: FILE:LINE: problem".
CameraPath load_path_option(const SceneInfo& info, const std::string& file);

// Sets `state`'s camera and parameters from the camera path `file` (path/camera_path.hpp) at
// the state's time, or at the path's start without --time. Throws a UsageError with the file's
// FILE:LINE problem.
void apply_camera_path(const SceneInfo& info, const std::string& file, const ParsedOptions& options,
                       SceneState& state);

// Throws a UsageError naming the limit when an image of the settings' size cannot be rendered on
// `device` in this process (render/memory_budget.hpp); `all_passes`: every pass is read back.
void check_memory(const RenderSettings& render, const DeviceInfo& device, bool all_passes);

}  // namespace fr
