#include "check/de_overestimate.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace fr {
namespace {

using Vec = std::array<double, 3>;

Vec unit(const Vec& v) {
  const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / len, v[1] / len, v[2] / len};
}

DePoint offset(const DePoint& p, const Vec& u, double t) {
  return {float(p[0] + u[0] * t), float(p[1] + u[1] * t), float(p[2] + u[2] * t)};
}

double distance(const DePoint& a, const DePoint& b) {
  const double dx = double(a[0]) - b[0], dy = double(a[1]) - b[1], dz = double(a[2]) - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace

DeOverestimate measure_de_overestimate(const DeBatch& de, const std::vector<DePoint>& points,
                                       const std::vector<float>& values, double bounding_radius,
                                       const DeOverestimateOptions& options,
                                       std::vector<double>* nearest) {
  DeOverestimate result;
  if (nearest) nearest->assign(points.size(), INFINITY);
  const double eps = options.surface_eps_rel * bounding_radius;
  // Candidates: outside the surface by at least 100 thresholds, so that a true distance, whose
  // ball ends exactly at the surface, is not judged by where the threshold cuts it (the ray
  // stops at most 1/100 of DE(p) early: ratios up to 100/99 for a true distance).
  std::vector<size_t> candidates;
  for (size_t i = 0; i < points.size() && i < values.size(); ++i)
    if (std::isfinite(values[i]) && values[i] >= 100 * eps) candidates.push_back(i);
  if (candidates.empty() || options.directions < 1 || options.steps_per_ray < 1) return result;
  // Spread over every distance: near the surface is where a marcher's steps are decided, far
  // from it is where a scaled DE's extra length is largest in absolute terms.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](size_t a, size_t b) { return values[a] < values[b]; });
  std::vector<size_t> tested;
  const size_t n = std::min(candidates.size(), std::max<size_t>(options.max_points, 1));
  for (size_t k = 0; k < n; ++k) tested.push_back(candidates[k * candidates.size() / n]);

  // The downhill direction by central differences (the nearest surface lies straight down the
  // gradient of a true distance).
  std::vector<DePoint> probes;
  for (size_t i : tested) {
    const double h = std::max(0.02 * values[i], 1e-6 * bounding_radius);
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        DePoint q = points[i];
        q[axis] = float(q[axis] + sign * h);
        probes.push_back(q);
      }
  }
  const std::vector<float> slopes = de(probes);

  // Every direction of every point, steps_per_ray fixed steps out to DE(p): one batch.
  const int dirs = options.directions, steps = options.steps_per_ray;
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  std::vector<Vec> directions;  // per tested point, `dirs` of them
  std::vector<DePoint> samples;
  samples.reserve(tested.size() * size_t(dirs) * size_t(steps));
  for (size_t k = 0; k < tested.size(); ++k) {
    const float* s = &slopes[6 * k];
    Vec down = {double(s[1]) - s[0], double(s[3]) - s[2], double(s[5]) - s[4]};
    const double len = std::sqrt(down[0] * down[0] + down[1] * down[1] + down[2] * down[2]);
    for (int d = 0; d < dirs; ++d) {
      Vec u;
      if (d == 0 && std::isfinite(len) && len > 0) {
        u = unit(down);
      } else {
        do u = {g(rng), g(rng), g(rng)};
        while (!(u[0] * u[0] + u[1] * u[1] + u[2] * u[2] > 1e-12));
        u = unit(u);
      }
      directions.push_back(u);
      const size_t i = tested[k];
      for (int j = 1; j <= steps; ++j)
        samples.push_back(offset(points[i], u, double(values[i]) * j / steps));
    }
  }
  const std::vector<float> along = de(samples);

  // The first step of each ray that lands on surface (NaN counts as surface: a marcher stops
  // there), then bisection between it and the step before, which was free, so that the ratio
  // below is the DE's, not the grid's. A ray may skip a surface thinner than its step; then the
  // ratio found is a lower bound of the true one (a coarse grid never invents an over-estimate).
  struct Crossing {
    size_t point;  // index into tested
    Vec u;
    double free_t, surface_t;
  };
  std::vector<Crossing> crossings;
  for (size_t k = 0; k < tested.size(); ++k)
    for (int d = 0; d < dirs; ++d) {
      const size_t base = (k * size_t(dirs) + size_t(d)) * size_t(steps);
      const double length = values[tested[k]];
      for (int j = 0; j < steps; ++j)
        if (!(along[base + size_t(j)] >= eps)) {
          crossings.push_back({k, directions[k * size_t(dirs) + size_t(d)], length * j / steps,
                               length * (j + 1) / steps});
          break;
        }
    }
  std::vector<DePoint> middles(crossings.size());
  for (int round = 0; round < 10 && !crossings.empty(); ++round) {
    for (size_t c = 0; c < crossings.size(); ++c)
      middles[c] = offset(points[tested[crossings[c].point]], crossings[c].u,
                          0.5 * (crossings[c].free_t + crossings[c].surface_t));
    const std::vector<float> at = de(middles);
    for (size_t c = 0; c < crossings.size(); ++c) {
      const double mid = 0.5 * (crossings[c].free_t + crossings[c].surface_t);
      (at[c] >= eps ? crossings[c].free_t : crossings[c].surface_t) = mid;
    }
  }

  std::vector<double> surface(tested.size(), INFINITY);
  std::vector<DePoint> surface_at(tested.size());
  for (const Crossing& c : crossings) {
    const DePoint q = offset(points[tested[c.point]], c.u, c.surface_t);
    const double t = distance(points[tested[c.point]], q);
    if (t < surface[c.point]) surface[c.point] = t, surface_at[c.point] = q;
  }
  for (size_t k = 0; k < tested.size(); ++k) {
    const size_t i = tested[k];
    if (nearest) (*nearest)[i] = surface[k];
    ++result.points_tested;
    if (!std::isfinite(surface[k])) continue;  // no surface inside the ball: nothing over
    const double ratio = double(values[i]) / surface[k];
    result.points_over += ratio > 1 + options.tolerance;
    if (ratio > result.worst_ratio) {
      result.worst_ratio = ratio;
      result.worst_at = points[i];
      result.worst_de = values[i];
      result.worst_surface = surface[k];
      result.worst_surface_at = surface_at[k];
    }
  }
  return result;
}

}  // namespace fr
