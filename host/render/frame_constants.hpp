// frame_constants.hpp — filling the struct shared with the kernels (kernels/frame_constants.h).
#pragma once

#include "scene/scene_data.hpp"

#include "render/camera.hpp"
#include "render/render_settings.hpp"

extern "C" {
#include "frame_constants.h"
}

namespace fr {

// The constants of sample `sample_index` (0, 1, ...) of a frame: sample 0 goes through pixel
// centres, later ones through jittered sub-pixel positions, mixed in with weight 1/(index + 1).
// `rays` is the whole image's camera (settings.window says which of its pixels this image has):
// the kernel computes a window's rays from the whole image's pixel grid, so that they are the
// whole image's bit for bit. The scene's bounding sphere is centred at `bounding_centre`: the
// origin, except for a double-double frame's eye-relative coordinates (render/eye_relative.hpp).
fr_frame_constants make_frame_constants(const CameraRays& rays, const SceneState& state,
                                        const RenderSettings& settings, int sample_index,
                                        glm::dvec3 bounding_centre = glm::dvec3(0.0));

// The scale besides |p| whose ulps floor the hit threshold (fr_frame_constants.
// threshold_floor_scale, kernels/rays.cl): the eye's distance from the bounding centre, at most
// the bounding radius. A ray's points are the eye's position plus a path, so they are no more
// precise than the eye's; every surface point lies within the bounding radius. And at least
// 1/1024 of the radius: an eye at a singular centre (the Mandelbulb's, where the estimate is 0
// and no surface) would otherwise have no floor at all, and its rays crawl for every step.
double threshold_floor_scale(double eye_distance, double bounding_radius);

// Sub-pixel offset of a sample, in (-0.5, 0.5)^2: (0, 0) for sample 0, then the R2 sequence
// (Roberts' additive recurrence), which covers the pixel evenly for any sample count.
std::array<double, 2> sample_jitter(int sample_index);

}  // namespace fr
