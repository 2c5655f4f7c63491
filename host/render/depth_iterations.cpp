#include "render/depth_iterations.hpp"

#include "render/eye_relative.hpp"
#include "render/precision.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace fr {

std::vector<RaisedIterations> raise_iterations_for_depth(const SceneInfo& info,
                                                         double bounding_radius, double distance,
                                                         double pixel_angle_rad,
                                                         std::vector<fr_value>& params) {
  std::vector<RaisedIterations> raised;
  const double footprint = distance * pixel_angle_rad;
  if (!(distance > 0) || !std::isfinite(distance) || !(footprint > 0) ||
      !(bounding_radius > distance))
    return raised;
  // (A count a hair off a step by rounding, log(3^40) / log(3) = 39.999..., counts as on it.)
  const auto step_down = [](double n) {
    return static_cast<int>(std::floor(n / kIterationStep + 1e-9)) * kIterationStep;
  };
  const auto step_up = [](double n) {
    return static_cast<int>(std::ceil(n / kIterationStep - 1e-9)) * kIterationStep;
  };
  for (size_t i = 0; i < info.params.size() && i < params.size(); ++i) {
    const ParamInfo& p = info.params[i];
    if (!(p.detail_ratio > 1)) continue;
    const double log_ratio = std::log(p.detail_ratio);
    // (A distance and footprint within double's range and a ratio above 1 keep these far below
    // int's range; capped anyway.)
    const double zoom = std::min(std::log(bounding_radius / distance) / log_ratio, 1e6);
    const double need = std::min(std::log(bounding_radius / footprint) / log_ratio, 1e6);
    const int set = static_cast<int>(params[i].v[0]);
    const int max = static_cast<int>(p.max_value.v[0]);
    const int wanted = std::max(set, std::min(set + step_down(zoom), step_up(need)));
    const int used = std::min(max, wanted);
    const int needed = static_cast<int>(std::ceil(need));
    const bool capped = wanted > max;
    if (used > set || capped) {
      params[i].v[0] = used;
      raised.push_back({p.key, set, used, needed, capped});  // (capped at set: said, not raised)
    }
  }
  return raised;
}

double eye_footprint(const DeProbe& probe, const SceneInfo& info, const SceneState& state,
                     const std::vector<fr_value>& params, int width_px, int height_px, bool fp64) {
  const CameraRays rays = view_camera_rays(state, width_px, height_px);
  const std::array<float, 3> eye{static_cast<float>(rays.eye.x), static_cast<float>(rays.eye.y),
                                 static_cast<float>(rays.eye.z)};
  const float de = probe(params, {eye}, fp64 ? Precision::Double : Precision::Float, nullptr)[0];
  double footprint = std::isfinite(de) ? std::max(double(de), 0.0) * rays.pixel_angle_rad : 0.0;
  if (fp64 && has_pair_estimate(info) &&
      footprint < kFloatFootprintUlps * float_resolution(state.bounding_radius)) {
    PairOrigin origin;
    const std::array<DoubleDouble, 3> eye_pair = eye_pairs(state.camera, state.camera_lo);
    std::copy(eye_pair.begin(), eye_pair.end(), origin.eye);
    const float pair_de = probe(params, {{0, 0, 0}}, Precision::DoubleDouble, &origin)[0];
    footprint =
        std::isfinite(pair_de) ? std::max(double(pair_de), 0.0) * rays.pixel_angle_rad : 0.0;
  }
  return footprint;
}

std::vector<RaisedIterations> raise_iterations_for_view(const DeProbe& probe,
                                                        const SceneInfo& info,
                                                        const SceneState& state, int width_px,
                                                        int height_px, bool fp64,
                                                        std::vector<fr_value>& params) {
  params = state.params;
  // An eye outside the bounding sphere is at least |eye| - R from the surface: where that alone
  // keeps every count's zoom under a step, nothing is added and nothing need be probed (a
  // scene's own view, its thumbnail).
  const CameraRays rays = view_camera_rays(state, width_px, height_px);
  const double outside = glm::length(rays.eye) - state.bounding_radius;
  bool may_add = false;
  for (const ParamInfo& p : info.params)
    if (p.detail_ratio > 1)
      may_add |= !(outside >= state.bounding_radius * std::pow(p.detail_ratio, -kIterationStep));
  if (!may_add) return {};
  const double pixel_angle = rays.pixel_angle_rad;
  const double first =
      eye_footprint(probe, info, state, state.params, width_px, height_px, fp64);
  std::vector<RaisedIterations> raised = raise_iterations_for_depth(
      info, state.bounding_radius, first / pixel_angle, pixel_angle, params);
  if (raised.empty()) return raised;
  std::vector<fr_value> most = state.params;
  for (size_t i = 0; i < info.params.size() && i < most.size(); ++i)
    if (info.params[i].detail_ratio > 1) most[i].v[0] = info.params[i].max_value.v[0];
  const double footprint = eye_footprint(probe, info, state, most, width_px, height_px, fp64);
  params = state.params;
  return raise_iterations_for_depth(info, state.bounding_radius, footprint / pixel_angle,
                                    pixel_angle, params);
}

std::string describe_raised(const std::vector<RaisedIterations>& raised) {
  std::string text;
  for (const RaisedIterations& r : raised) {
    if (!text.empty()) text += "; ";
    text += r.key + " " + std::to_string(r.used);
    if (r.used > r.set) text += " (set " + std::to_string(r.set) + ")";
    if (r.capped)
      text += ", its max (the view asks for more: " + std::to_string(r.needed) + ")";
  }
  return text;
}

}  // namespace fr
