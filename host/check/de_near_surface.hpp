// de_near_surface.hpp — does the DE over-estimate close to the surface, where a marcher's steps
// are decided?
//
// de_overestimate samples the whole bounding sphere, where an escape-time DE such as the
// Mandelbox's under-estimates several-fold: that DE multiplied by 3 still looks safe there, yet
// near the surface it steps three times too far. This check finds surface first, without trusting
// the DE's values: many rays cross the bounding ball in small fixed steps, and the first step
// below the surface threshold is bisected back to where the surface begins. From each surface
// point it then steps off by known small distances t — along the DE's outward gradient and back
// along the ray — to points whose distance to the surface is at most t (that surface point is t
// away). A DE above (1 + tolerance) t there promises empty space that holds surface.
//
// Deterministic (fixed seeds); the DE is a batch evaluator, as for de_overestimate, so the tests
// run it against exact geometry.
#pragma once

#include "check/de_overestimate.hpp"

#include <vector>

namespace fr {

struct DeNearSurfaceOptions {
  int rays = 384;                 // from the bounding sphere across its ball
  int steps_per_ray = 1024;       // fixed steps over the ray's chord (2 R at most)
  double surface_eps_rel = 1e-5;  // DE below this times R counts as surface
  std::vector<double> offsets_rel = {1e-3, 4e-3, 1.6e-2};  // t, times R (100x the threshold up)
  double tolerance = 0.1;         // an over-estimate is DE > (1 + tolerance) t
  int search_directions = 24;     // per offset point, for nearer surface than t
};

struct DeNearSurface {
  size_t surface_points = 0;  // crossings found and bisected
  size_t points_tested = 0;   // offset points outside the surface
  size_t points_over = 0;     // of those, DE > (1 + tolerance) t
  double worst_ratio = 0;     // largest DE / t
  DePoint worst_at{};
  double worst_de = 0, worst_t = 0;
  double percent_over() const {
    return points_tested ? 100.0 * double(points_over) / double(points_tested) : 0.0;
  }
};

DeNearSurface measure_de_near_surface(const DeBatch& de, double bounding_radius,
                                      const DeNearSurfaceOptions& options = {});

}  // namespace fr
