#include "app/reprojection.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace fr {

ReprojectedFrame reproject(const CameraRays& old_rays, const uint8_t* old_rgba8,
                           const float* old_depth, const CameraRays& new_rays) {
  ReprojectedFrame out;
  out.width_px = new_rays.width_px;
  out.height_px = new_rays.height_px;
  const size_t n = static_cast<size_t>(out.width_px) * out.height_px;
  out.rgba8.assign(n * 4, 0);
  out.depth.assign(n, std::numeric_limits<float>::infinity());
  out.reused.assign(n, 0);
  for (int y = 0; y < old_rays.height_px; ++y)
    for (int x = 0; x < old_rays.width_px; ++x) {
      const size_t from = static_cast<size_t>(y) * old_rays.width_px + x;
      const float t = old_depth[from];
      if (!std::isfinite(t)) continue;  // sky: traced fresh
      const glm::dvec3 point = old_rays.eye + camera_ray_dir(old_rays, x, y) * double(t);
      const auto at = camera_project(new_rays, point);
      if (!at) continue;
      const double nx = std::round(at->x), ny = std::round(at->y);
      if (nx < 0 || ny < 0 || nx > out.width_px - 1 || ny > out.height_px - 1) continue;
      const size_t to = static_cast<size_t>(ny) * out.width_px + static_cast<size_t>(nx);
      const float distance = static_cast<float>(glm::length(point - new_rays.eye));
      if (distance >= out.depth[to]) continue;  // something nearer landed here
      if (!out.reused[to]) ++out.reused_count;
      out.reused[to] = 1;
      out.depth[to] = distance;
      for (int c = 0; c < 4; ++c) out.rgba8[to * 4 + c] = old_rgba8[from * 4 + c];
    }
  return out;
}

}  // namespace fr
