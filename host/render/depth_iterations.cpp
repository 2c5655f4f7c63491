#include "render/depth_iterations.hpp"

#include "render/eye_relative.hpp"
#include "render/precision.hpp"

#include <algorithm>
#include <cmath>

namespace fr {

std::vector<RaisedIterations> raise_iterations_for_footprint(const SceneInfo& info,
                                                             double bounding_radius,
                                                             double footprint,
                                                             std::vector<fr_value>& params) {
  std::vector<RaisedIterations> raised;
  if (!(footprint > 0) || !std::isfinite(footprint) || !(bounding_radius > footprint)) return raised;
  for (size_t i = 0; i < info.params.size() && i < params.size(); ++i) {
    const ParamInfo& p = info.params[i];
    if (!(p.detail_ratio > 1)) continue;
    const double needed_real = std::log(bounding_radius / footprint) / std::log(p.detail_ratio);
    // (A footprint within the double range and a ratio above 1 keep this far below int's range.)
    const int needed = static_cast<int>(std::ceil(std::min(needed_real, 1e6)));
    const int set = static_cast<int>(params[i].v[0]);
    if (needed <= set) continue;
    const int stepped = (needed + kIterationStep - 1) / kIterationStep * kIterationStep;
    const int used = std::min(stepped, static_cast<int>(p.max_value.v[0]));
    if (used <= set) {
      raised.push_back({p.key, set, set, needed});  // already at its max: said, not raised
      continue;
    }
    params[i].v[0] = used;
    raised.push_back({p.key, set, used, needed});
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
  const double first =
      eye_footprint(probe, info, state, state.params, width_px, height_px, fp64);
  std::vector<RaisedIterations> raised =
      raise_iterations_for_footprint(info, state.bounding_radius, first, params);
  if (raised.empty()) return raised;
  std::vector<fr_value> most = state.params;
  for (size_t i = 0; i < info.params.size() && i < most.size(); ++i)
    if (info.params[i].detail_ratio > 1) most[i].v[0] = info.params[i].max_value.v[0];
  const double footprint = eye_footprint(probe, info, state, most, width_px, height_px, fp64);
  params = state.params;
  return raise_iterations_for_footprint(info, state.bounding_radius, footprint, params);
}

std::string describe_raised(const std::vector<RaisedIterations>& raised) {
  std::string text;
  for (const RaisedIterations& r : raised) {
    if (!text.empty()) text += "; ";
    text += r.key + " " + std::to_string(r.used);
    if (r.used > r.set) text += " (set " + std::to_string(r.set) + ")";
    if (r.needed > r.used)
      text += ", the view needs " + std::to_string(r.needed) + " but that is its max";
  }
  return text;
}

}  // namespace fr
