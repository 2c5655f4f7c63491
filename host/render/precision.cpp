#include "render/precision.hpp"

#include "render/de_probe.hpp"
#include "render/eye_relative.hpp"
#include "render/frame_constants.hpp"
#include "render/kernel_assembly.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace fr {

double float_resolution(double position_scale) {
  return std::abs(position_scale) * FLT_EPSILON;
}

namespace {
// The largest |p| a hit `distance` from the eye can have (float_resolves_beyond explains).
double hit_position_scale(double distance, const CameraRays& rays, double bounding_radius) {
  const double eye_distance = glm::length(rays.eye);
  return std::max(threshold_floor_scale(eye_distance, bounding_radius),
                  std::min(eye_distance + distance, bounding_radius));
}
}  // namespace

bool float_resolves_beyond(double distance, const CameraRays& rays, double bounding_radius) {
  // Every surface point lies within the bounding radius: a hit t from the eye is at most
  // min(|eye| + t, R) from the centre, and its footprint t x pixel angle over that grows with t.
  // So the nearest hit's is the least, and float resolves every hit of the view when it resolves
  // a footprint at distance t on positions of min(|eye| + t, R) (or the threshold floor's own
  // scale, where that is more: ulps of max(|p|, threshold_floor_scale) floor the kernel's hit
  // threshold), and the floor is then under a quarter of every hit's footprint. (An imported
  // view's bound reaches as far as Mandelbulber2 could see, tens of units: its close-ups are
  // judged at the eye's scale.)
  if (!(distance >= 0)) return false;
  if (std::isinf(distance)) return true;  // nothing to hit
  return distance * rays.pixel_angle_rad >=
         kFloatFootprintUlps *
             float_resolution(hit_position_scale(distance, rays, bounding_radius));
}

Precision resolve_precision(ClRuntime& runtime, const SceneInfo& info, const SceneState& state,
                            const RenderSettings& settings) {
  if (settings.precision != Precision::Auto) return settings.precision;
  if (!runtime.device().has_fp64) return Precision::Float;
  const CameraRays rays = view_camera_rays(state, settings.width_px, settings.height_px,
                                           settings.mirror_vertical, settings.pixel_corners);
  const std::array<float, 3> eye{static_cast<float>(rays.eye.x), static_cast<float>(rays.eye.y),
                                 static_cast<float>(rays.eye.z)};
  const float de = probe_de(runtime, info, state.params, {eye}, 1, Precision::Double)[0];
  // The nearest surface is at least |DE| away (float_resolves_beyond).
  const double distance = std::isfinite(de) ? std::abs(double(de)) : 0.0;
  if (float_resolves_beyond(distance, rays, state.bounding_radius)) return Precision::Float;
  const double position_scale = hit_position_scale(distance, rays, state.bounding_radius);
  if (!has_pair_estimate(info) || settings.integrator == Integrator::Path || settings.fast_math)
    return Precision::Double;
  // Past float: ask again in pairs, at the eye itself (the probe above saw it rounded to float,
  // and a double estimate there is only as good as double's resolution).
  PairOrigin origin;
  const std::array<DoubleDouble, 3> eye_pair = eye_pairs(state.camera, state.camera_lo);
  std::copy(eye_pair.begin(), eye_pair.end(), origin.eye);
  const float pair_de =
      probe_de(runtime, info, state.params, {{0, 0, 0}}, 1, Precision::DoubleDouble, &origin)[0];
  const double pair_distance = std::isfinite(pair_de) ? std::abs(double(pair_de)) : 0.0;
  const double pair_footprint = pair_distance * rays.pixel_angle_rad;
  if (pair_footprint >= kDoubleFootprintUlps * double_resolution(position_scale))
    return Precision::Double;
  // Pairs only where they resolve more than double would at these parameters.
  const PairProbe probe = [&](const std::vector<std::array<float, 3>>& points,
                              const PairOrigin& at) {
    return probe_de(runtime, info, state.params, points, 1, Precision::DoubleDouble, &at);
  };
  return pair_estimate_resolves(probe, eye_pair, pair_footprint) ? Precision::DoubleDouble
                                                                 : Precision::Double;
}

bool pair_estimate_resolves(const PairProbe& probe, const std::array<DoubleDouble, 3>& eye,
                            double footprint) {
  if (!(footprint > 0) || !std::isfinite(footprint)) return true;
  constexpr int kPoints = 8;
  const double spacing = 0.25 * footprint;
  // Only axes along which the points (1.75 footprints) span less than half an ulp of the eye's
  // coordinate tell: along the others double sees the steps too.
  std::vector<int> axes;
  std::vector<std::array<float, 3>> points;
  for (int axis = 0; axis < 3; ++axis) {
    const double x = std::abs(eye[axis].hi);
    if (!(2 * footprint < std::nextafter(x, INFINITY) - x)) continue;
    axes.push_back(axis);
    for (int k = 0; k < kPoints; ++k) {
      std::array<float, 3> q{0, 0, 0};
      q[axis] = static_cast<float>(k * spacing);
      points.push_back(q);
    }
  }
  if (axes.empty()) return true;
  PairOrigin origin;
  std::copy(eye.begin(), eye.end(), origin.eye);
  const std::vector<float> values = probe(points, origin);
  for (size_t a = 0; a < axes.size(); ++a) {
    std::vector<float> line(values.begin() + a * kPoints, values.begin() + (a + 1) * kPoints);
    std::sort(line.begin(), line.end());
    if (std::unique(line.begin(), line.end()) - line.begin() >= 6) return true;
  }
  return false;
}

bool pair_estimate_resolves_view(const PairProbe& probe, const SceneState& state,
                                 const CameraRays& rays) {
  const std::array<DoubleDouble, 3> eye = eye_pairs(state.camera, state.camera_lo);
  PairOrigin origin;
  std::copy(eye.begin(), eye.end(), origin.eye);
  const float de = probe({{0, 0, 0}}, origin)[0];
  if (!std::isfinite(de)) return true;
  return pair_estimate_resolves(probe, eye, std::abs(double(de)) * rays.pixel_angle_rad);
}

double double_resolution(double position_scale) {
  return std::abs(position_scale) * DBL_EPSILON;
}

void check_pair_frame(const SceneInfo& info, const RenderSettings& settings) {
  if (!has_pair_estimate(info))
    throw std::invalid_argument(
        "render.precision dd: scene '" + info.id +
        "' has no pair estimate (a scene_de_dd in its DE source; docs/deep_zoom.md): the "
        "Mandelbox, Menger and Mandelbulb scenes have one");
  if (settings.integrator == Integrator::Path)
    throw std::invalid_argument(
        "render.precision dd: the path tracer does not work in pairs yet; render with "
        "render.integrator = \"fast\"");
  if (settings.fast_math)
    throw std::invalid_argument(
        "render.precision dd: render.fast_math would drop the pairs' error terms; turn it off");
}

double position_epsilon(Precision precision) {
  switch (precision) {
    case Precision::Float:
      return FLT_EPSILON;
    case Precision::DoubleDouble:
      return 0x1p-104;
    default:
      return DBL_EPSILON;
  }
}

CameraRays view_camera_rays(const SceneState& state, int width_px, int height_px,
                            bool mirror_vertical, bool pixel_corners) {
  const std::array<double, 3> view = view_vector(state.camera, state.camera_lo);
  fr_camera relative = state.camera;
  for (int i = 0; i < 3; ++i) {
    relative.eye[i] = 0;
    relative.target[i] = view[i];
  }
  CameraRays rays = make_camera_rays(relative, width_px, height_px, mirror_vertical, pixel_corners);
  const std::array<DoubleDouble, 3> eye = eye_pairs(state.camera, state.camera_lo);
  rays.eye = glm::dvec3(eye[0].hi, eye[1].hi, eye[2].hi);
  return rays;
}

size_t pixels_below_resolution(const std::vector<float>& depth, const CameraRays& rays,
                               Precision precision) {
  size_t n = 0;
  const double epsilon = position_epsilon(precision);
  for (int y = 0; y < rays.height_px; ++y)
    for (int x = 0; x < rays.width_px; ++x) {
      const float t = depth[static_cast<size_t>(y) * rays.width_px + x];
      if (!std::isfinite(t)) continue;
      const glm::dvec3 p = rays.eye + camera_ray_dir(rays, x, y) * double(t);
      n += double(t) * rays.pixel_angle_rad < kFloatFootprintUlps * epsilon * glm::length(p);
    }
  return n;
}

}  // namespace fr
