// de_overestimate.hpp — does the DE claim more empty space than there is?
//
// Sphere tracing is only right if the ball of radius DE(p) around p holds no surface. A DE that
// is too large by a constant factor can still have a slope near or below 1 at every sampled pair
// (a Mandelbox-style DE whose true bound is well below 1 scaled up, say), so the finite-difference
// Lipschitz check cannot see it. This looks for surface inside the ball directly: from each
// sampled point outside the surface it walks fixed, DE-independent steps along the DE's downhill
// direction (where the nearest surface lies for a true distance) and along a spread of other
// directions, takes the first step whose DE is below the surface threshold as surface, and
// bisects back to where the surface begins. The over-estimate at p is DE(p) over the distance to
// the nearest surface so found.
//
// The DE is passed in as a batch evaluator, so the same code runs against the scene's OpenCL DE
// in `fractalis check` and against exact C++ geometry in the tests.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace fr {

using DePoint = std::array<float, 3>;
// DE values at a batch of points (one call per batch: the device evaluates them together).
using DeBatch = std::function<std::vector<float>(const std::vector<DePoint>&)>;

struct DeOverestimateOptions {
  double surface_eps_rel = 1e-5;  // DE below this times the bounding radius counts as surface
  int directions = 24;            // per point: the downhill one and directions - 1 others
  int steps_per_ray = 64;         // fixed steps from p out to DE(p), then 10 bisections
  size_t max_points = 512;        // points tested (spread over the candidates by distance)
  double tolerance = 0.1;         // an over-estimate is DE(p) > (1 + tolerance) x distance
};

struct DeOverestimate {
  size_t points_tested = 0;    // points outside the surface, far enough from it to judge
  size_t points_over = 0;      // of those, where DE(p) > (1 + tolerance) x surface distance
  double worst_ratio = 0;      // largest DE(p) / surface distance found (0: no surface seen)
  DePoint worst_at{};          // where
  double worst_de = 0;         // DE there
  double worst_surface = 0;    // and the distance to the surface found from there
  DePoint worst_surface_at{};  // the surface point itself
  double percent_over() const {
    return points_tested ? 100.0 * double(points_over) / double(points_tested) : 0.0;
  }
};

// `points` and `values` are candidate points and their DE (already evaluated); those with a DE
// of at least 100 surface thresholds are tested. Deterministic: the same inputs give the same
// answer.
// With `nearest`, it also receives, for each of `points`, the distance to the nearest surface
// the search found (infinity where it found none or did not test the point).
DeOverestimate measure_de_overestimate(const DeBatch& de, const std::vector<DePoint>& points,
                                       const std::vector<float>& values, double bounding_radius,
                                       const DeOverestimateOptions& options = {},
                                       std::vector<double>* nearest = nullptr);

}  // namespace fr
