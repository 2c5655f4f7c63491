// frame_constants.hpp — filling the struct shared with the kernels (kernels/frame_constants.h).
#pragma once

#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/render_settings.hpp"

extern "C" {
#include "frame_constants.h"
}

namespace fr {

fr_frame_constants make_frame_constants(const CameraRays& rays, const SceneState& state,
                                        const RenderSettings& settings);

}  // namespace fr
