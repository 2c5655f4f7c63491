// reprojection.hpp — the previous frame carried into a new camera (temporal reuse while flying,
// issue 37): each surface pixel of the old frame is the point its ray hit (the eye plus its depth
// along its ray); that point lands at a pixel of the new image, nearest first where several land
// on one (a depth test). Pixels nothing lands on (disoccluded, or beyond the old image's edge)
// and sky pixels are left to be traced fresh. The host's reference, in double: what a kernel
// doing the same must match.
#pragma once

#include "render/camera.hpp"

#include <cstdint>
#include <vector>

namespace fr {

struct ReprojectedFrame {
  int width_px = 0;
  int height_px = 0;
  std::vector<uint8_t> rgba8;   // the reused colour; zero where fresh
  std::vector<float> depth;     // distance along the new ray to the reused point; +inf where fresh
  std::vector<uint8_t> reused;  // 1: a reused pixel, 0: to be traced
  size_t reused_count = 0;
};

// `old_rgba8` and `old_depth` (distance along each ray, +inf for a miss) are the frame rendered
// with `old_rays`; the result has `new_rays`' size.
ReprojectedFrame reproject(const CameraRays& old_rays, const uint8_t* old_rgba8,
                           const float* old_depth, const CameraRays& new_rays);

}  // namespace fr
