#include "sweep/sweep_metrics.hpp"

#include "bench/frame_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace fr {

FrameImage reference_as_frame(const ReferenceImage& r) {
  FrameImage f;
  f.width_px = r.width_px;
  f.height_px = r.height_px;
  f.rgba8 = r.rgba8;
  f.depth = r.depth;
  f.normal = r.normal;
  f.ray_status.resize(r.depth.size());
  for (size_t i = 0; i < r.depth.size(); ++i)
    f.ray_status[i] = uint8_t(std::isfinite(r.depth[i]) ? RayStatus::Hit : RayStatus::Miss);
  return f;
}

ErrorMetrics compare_to_reference(const FrameImage& image, const ReferenceImage& ref,
                                  double pixel_angle_rad) {
  const size_t n = static_cast<size_t>(ref.width_px) * ref.height_px;
  if (image.rgba8.size() != n * 4 || image.depth.size() != n || image.normal.size() != n * 3 ||
      ref.rgba8.size() != n * 4 || ref.depth.size() != n || ref.normal.size() != n * 3)
    throw std::invalid_argument("compare_to_reference: image and reference sizes differ");
  ErrorMetrics m;
  double abs_sum = 0, square_sum = 0;
  size_t over_8 = 0, mismatch = 0, reference_hits = 0, oversteps = 0;
  std::vector<double> depth_px, angle_deg;
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(image.rgba8[4 * i + c]) - int(ref.rgba8[4 * i + c]));
      abs_sum += d;
      square_sum += double(d) * d;
      worst = std::max(worst, d);
    }
    over_8 += worst > 8;
    const float t = image.depth[i], t_ref = ref.depth[i];
    const bool hit = std::isfinite(t), ref_hit = std::isfinite(t_ref);
    m.non_finite += std::isnan(t) || t == -INFINITY;
    for (int c = 0; c < 3; ++c) m.non_finite += !std::isfinite(image.normal[3 * i + c]);
    mismatch += hit != ref_hit;
    reference_hits += ref_hit;
    if (!(hit && ref_hit)) continue;
    const double footprint = std::max(double(t_ref) * pixel_angle_rad, 1e-30);
    const double error = (double(t) - double(t_ref)) / footprint;
    depth_px.push_back(std::abs(error));
    oversteps += error > kOverstepFootprints;
    double dot = 0;
    for (int c = 0; c < 3; ++c) dot += double(image.normal[3 * i + c]) * ref.normal[3 * i + c];
    angle_deg.push_back(std::acos(std::clamp(dot, -1.0, 1.0)) * 180 / std::numbers::pi);
  }
  for (uint8_t s : image.ray_status) m.out_of_steps_fraction += s == uint8_t(RayStatus::OutOfSteps);
  m.out_of_steps_fraction /= double(std::max<size_t>(n, 1));
  m.mean_abs_error = abs_sum / double(3 * n);
  const double rms = std::sqrt(square_sum / double(3 * n));
  m.psnr_db = rms > 0 ? 20 * std::log10(255.0 / rms) : std::numeric_limits<double>::infinity();
  m.fraction_over_8 = double(over_8) / double(n);
  m.silhouette_mismatch = double(mismatch) / double(n);
  m.depth_median_px = percentile(depth_px, 50);
  m.depth_p95_px = percentile(depth_px, 95);
  m.normal_p95_deg = percentile(angle_deg, 95);
  m.overstep_rate = reference_hits ? double(oversteps) / double(reference_hits) : 0;
  return m;
}

std::vector<size_t> pareto_front(const std::vector<double>& time,
                                 const std::vector<double>& error) {
  std::vector<size_t> order(time.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return time[a] != time[b] ? time[a] < time[b] : error[a] < error[b];
  });
  std::vector<size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i : order)
    if (error[i] < best) {
      front.push_back(i);
      best = error[i];
    }
  return front;
}

}  // namespace fr
