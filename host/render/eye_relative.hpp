// eye_relative.hpp — a double-double frame's view of the scene (render.precision "dd",
// docs/deep_zoom.md): the same scene with the camera's eye moved to the origin.
//
// Such a kernel works in double relative to the eye and hands only the scene's estimate the
// absolute point, as pairs (kernels/dd_relative.cl). On the host that means: the camera at the
// origin looking along target - eye worked out from the pairs (scene_data.hpp, view_vector),
// point lights moved by -eye, the bounding sphere centred at -eye, and the eye itself as pairs at
// the end of the parameter block.
#pragma once

#include "render/kernel_assembly.hpp"  // PairOrigin
#include "scene/scene_data.hpp"

#include <glm/vec3.hpp>

#include <array>

namespace fr {

struct EyeRelativeView {
  SceneState state;            // the camera's eye at the origin, camera_lo zero
  PairOrigin origin;           // the eye as pairs, and the resolution angle
  glm::dvec3 bounding_centre;  // -eye, rounded to double
};

// The camera's eye as pairs (hi the nearest double to eye + eye_lo).
std::array<DoubleDouble, 3> eye_pairs(const fr_camera& camera, const CameraLow& low);

// `resolution_rad`: what the estimate must resolve over the distance from the eye (the pixel
// angle, or the hit threshold's angle where that is finer).
EyeRelativeView eye_relative_view(const SceneState& world, double resolution_rad);

}  // namespace fr
