#include "render/precision.hpp"

#include "render/de_probe.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace fr {

double float_resolution(double position_scale) {
  return std::abs(position_scale) * FLT_EPSILON;
}

Precision resolve_precision(ClRuntime& runtime, const SceneInfo& info, const SceneState& state,
                            const RenderSettings& settings) {
  if (settings.precision != Precision::Auto) return settings.precision;
  if (!runtime.device().has_fp64) return Precision::Float;
  const CameraRays rays = make_camera_rays(state.camera, settings.width_px, settings.height_px);
  const std::array<float, 3> eye{static_cast<float>(rays.eye.x), static_cast<float>(rays.eye.y),
                                 static_cast<float>(rays.eye.z)};
  const float de = probe_de(runtime, info, state.params, {eye}, 1, Precision::Double)[0];
  // The nearest surface is at least |DE| away. The hit threshold never falls below a few ulps of
  // max(|p|, bounding radius) (kernels/rays.cl), so the bounding radius is the scale float must
  // resolve a footprint at: a scene bounded generously (an imported view's, to everything
  // Mandelbulber2 could see) needs double sooner than its eye's distance alone would say.
  const double distance = std::isfinite(de) ? std::abs(double(de)) : 0.0;
  const double position_scale = state.bounding_radius;
  const double footprint = distance * rays.pixel_angle_rad;
  return footprint < kFloatFootprintUlps * float_resolution(position_scale) ? Precision::Double
                                                                            : Precision::Float;
}

size_t pixels_below_float_resolution(const std::vector<float>& depth, const CameraRays& rays) {
  size_t n = 0;
  for (int y = 0; y < rays.height_px; ++y)
    for (int x = 0; x < rays.width_px; ++x) {
      const float t = depth[static_cast<size_t>(y) * rays.width_px + x];
      if (!std::isfinite(t)) continue;
      const glm::dvec3 p = rays.eye + camera_ray_dir(rays, x, y) * double(t);
      n +=
          double(t) * rays.pixel_angle_rad < kFloatFootprintUlps * float_resolution(glm::length(p));
    }
  return n;
}

}  // namespace fr
