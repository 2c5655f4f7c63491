// exact_shapes.hpp — exact ray casts against shapes with known geometry, in double: what the
// rendering tests compare the renderer with.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fr::test {

using glm::dvec3;
inline constexpr double kNone = std::numeric_limits<double>::infinity();

// Entry distance of the ray into the axis-aligned box centre +- half (0 if it starts inside).
inline double box_entry(dvec3 o, dvec3 d, dvec3 centre, double half) {
  double t0 = 0, t1 = kNone;
  for (int a = 0; a < 3; ++a) {
    const double lo = centre[a] - half, hi = centre[a] + half;
    if (d[a] == 0) {
      if (o[a] < lo || o[a] > hi) return kNone;
      continue;
    }
    double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return kNone;
  }
  return t0;
}

// The level-n sponge in the cube centre +- half, each leaf cube grown by `grow`. Sub-cubes are
// visited nearest first and skipped once their box is entered behind the best hit so far, so a
// level-8 sponge costs a few thousand box tests per ray.
inline double menger_entry(dvec3 o, dvec3 d, dvec3 centre, double half, int level, double grow) {
  const double t_box = box_entry(o, d, centre, half + grow);
  if (t_box == kNone || level == 0) return t_box;
  struct Child {
    double t;
    dvec3 centre;
  };
  Child children[20];
  int n = 0;
  const double third = half / 3;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        if ((i == 0) + (j == 0) + (k == 0) >= 2) continue;  // the removed cross
        const dvec3 c = centre + 2 * third * dvec3(i, j, k);
        const double t = box_entry(o, d, c, third + grow);
        if (t != kNone) children[n++] = {t, c};
      }
  std::sort(children, children + n, [](const Child& a, const Child& b) { return a.t < b.t; });
  double best = kNone;
  for (int c = 0; c < n && children[c].t < best; ++c)
    best = std::min(best, menger_entry(o, d, children[c].centre, third, level - 1, grow));
  return best;
}

// First intersection of the ray o + t d (d unit) with the sphere |p| = radius; kNone if none
// ahead. *closest receives the ray's closest distance to the centre.
inline double sphere_entry(dvec3 o, dvec3 d, double radius, double* closest = nullptr) {
  const double b = glm::dot(o, d), c = glm::dot(o, o) - radius * radius;
  if (closest) *closest = std::sqrt(std::max(glm::dot(o, o) - b * b, 0.0));
  const double disc = b * b - c;
  if (disc < 0) return kNone;
  const double t = -b - std::sqrt(disc);
  return t >= 0 ? t : (-b + std::sqrt(disc) >= 0 ? 0 : kNone);
}

}  // namespace fr::test
