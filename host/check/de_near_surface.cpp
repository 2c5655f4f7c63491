#include "check/de_near_surface.hpp"

#include <cmath>
#include <random>

namespace fr {
namespace {

using Vec = std::array<double, 3>;

Vec unit(Vec v) {
  const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / len, v[1] / len, v[2] / len};
}

DePoint along(const Vec& from, const Vec& u, double t) {
  return {float(from[0] + u[0] * t), float(from[1] + u[1] * t), float(from[2] + u[2] * t)};
}

}  // namespace

DeNearSurface measure_de_near_surface(const DeBatch& de, double bounding_radius,
                                      const DeNearSurfaceOptions& options) {
  DeNearSurface result;
  const double r = bounding_radius;
  const double eps = options.surface_eps_rel * r;
  const int steps = std::max(options.steps_per_ray, 2);
  // Rays from points on the bounding sphere towards points inside 0.6 R: they cross the middle
  // of the ball, where the surface is, from every side.
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u01(0, 1);
  auto random_unit = [&] {
    Vec v;
    do v = {g(rng), g(rng), g(rng)};
    while (!(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > 1e-12));
    return unit(v);
  };
  struct Ray {
    Vec origin, u;
    double length;
  };
  std::vector<Ray> rays;
  for (int i = 0; i < options.rays; ++i) {
    const Vec o = random_unit();
    const Vec t = random_unit();
    const double reach = 0.6 * r * std::cbrt(u01(rng));
    const Vec from = {o[0] * r, o[1] * r, o[2] * r};
    const Vec to = {t[0] * reach, t[1] * reach, t[2] * reach};
    const Vec d = {to[0] - from[0], to[1] - from[1], to[2] - from[2]};
    const Vec u = unit(d);
    // Through the whole ball: the chord's length from the entry point.
    const double length = -2 * (from[0] * u[0] + from[1] * u[1] + from[2] * u[2]);
    rays.push_back({from, u, std::max(length, 0.0)});
  }
  std::vector<DePoint> samples;
  samples.reserve(rays.size() * size_t(steps));
  for (const Ray& ray : rays)
    for (int j = 1; j <= steps; ++j) samples.push_back(along(ray.origin, ray.u, ray.length * j / steps));
  const std::vector<float> values = de(samples);

  // The first step on surface (NaN counts as surface), bisected between it and the free step
  // before it.
  struct Crossing {
    size_t ray;
    double free_t, surface_t;
  };
  std::vector<Crossing> crossings;
  for (size_t k = 0; k < rays.size(); ++k)
    for (int j = 0; j < steps; ++j)
      if (!(values[k * size_t(steps) + size_t(j)] >= eps)) {
        crossings.push_back({k, rays[k].length * j / steps, rays[k].length * (j + 1) / steps});
        break;
      }
  std::vector<DePoint> middles(crossings.size());
  for (int round = 0; round < 24 && !crossings.empty(); ++round) {
    for (size_t c = 0; c < crossings.size(); ++c)
      middles[c] = along(rays[crossings[c].ray].origin, rays[crossings[c].ray].u,
                         0.5 * (crossings[c].free_t + crossings[c].surface_t));
    const std::vector<float> at = de(middles);
    for (size_t c = 0; c < crossings.size(); ++c) {
      const double mid = 0.5 * (crossings[c].free_t + crossings[c].surface_t);
      (at[c] >= eps ? crossings[c].free_t : crossings[c].surface_t) = mid;
    }
  }
  result.surface_points = crossings.size();
  if (crossings.empty()) return result;

  // The outward direction at each surface point: the DE's gradient, by central differences a
  // little outside (where the DE is defined and positive), and back along the ray.
  std::vector<Vec> surface(crossings.size());
  std::vector<DePoint> probes;
  const double h = 1e-4 * r;
  for (size_t c = 0; c < crossings.size(); ++c) {
    const Ray& ray = rays[crossings[c].ray];
    const double t = crossings[c].surface_t;
    surface[c] = {ray.origin[0] + ray.u[0] * t, ray.origin[1] + ray.u[1] * t,
                  ray.origin[2] + ray.u[2] * t};
    const Vec outside = {surface[c][0] - ray.u[0] * 4 * h, surface[c][1] - ray.u[1] * 4 * h,
                         surface[c][2] - ray.u[2] * 4 * h};
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        Vec q = outside;
        q[axis] += sign * h;
        probes.push_back(along(q, {0, 0, 0}, 0));
      }
  }
  const std::vector<float> slopes = de(probes);
  std::vector<DePoint> tests;
  std::vector<double> test_t;
  for (size_t c = 0; c < crossings.size(); ++c) {
    const float* s = &slopes[6 * c];
    const Vec grad = {double(s[0]) - s[1], double(s[2]) - s[3], double(s[4]) - s[5]};
    const double len = std::sqrt(grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2]);
    const Ray& ray = rays[crossings[c].ray];
    const Vec back = {-ray.u[0], -ray.u[1], -ray.u[2]};
    for (double rel : options.offsets_rel) {
      const double t = rel * r;
      if (std::isfinite(len) && len > 0) {
        tests.push_back(along(surface[c], {grad[0] / len, grad[1] / len, grad[2] / len}, t));
        test_t.push_back(t);
      }
      if (t < crossings[c].surface_t) {  // the ray's own free side, inside the ball
        tests.push_back(along(surface[c], back, t));
        test_t.push_back(t);
      }
    }
  }
  const std::vector<float> at = de(tests);
  // The offset point is at most t from the surface point it came from, but a rough surface (a
  // fractal's) has other surface nearer still: search each point's own ball as de-overestimate
  // does (the downhill direction and 23 others, fixed steps out to DE(p), bisected), and compare
  // DE(p) with the nearest surface found, or with t where that is nearer.
  std::vector<DePoint> outside;
  std::vector<float> outside_de;
  std::vector<double> outside_t;
  for (size_t i = 0; i < tests.size(); ++i)
    if (at[i] >= eps) {  // back inside the surface (a thin wall, a fold) says nothing
      outside.push_back(tests[i]);
      outside_de.push_back(at[i]);
      outside_t.push_back(test_t[i]);
    }
  DeOverestimateOptions search;
  search.surface_eps_rel = options.surface_eps_rel;
  search.tolerance = options.tolerance;
  search.max_points = outside.size();
  search.directions = options.search_directions;
  std::vector<double> nearest;
  const DeOverestimate found =
      measure_de_overestimate(de, outside, outside_de, bounding_radius, search, &nearest);
  for (size_t i = 0; i < outside.size(); ++i) {
    const double distance = std::min(outside_t[i], nearest[i]);
    ++result.points_tested;
    const double ratio = double(outside_de[i]) / distance;
    result.points_over += ratio > 1 + options.tolerance;
    if (ratio > result.worst_ratio) {
      result.worst_ratio = ratio;
      result.worst_at = outside[i];
      result.worst_de = outside_de[i];
      result.worst_t = distance;
    }
  }
  (void)found;
  return result;
}

}  // namespace fr
