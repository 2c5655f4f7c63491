// The over-estimate search of `fractalis check` (check/de_overestimate.cpp) against exact
// geometry in double precision: true distances to a sphere and to a box pass, the same distances
// multiplied by k fail with the worst ratio k, a DE that is too short is never "over", and a DE
// that is too long only near the surface (where a marcher decides its last steps) is caught.
#include "check/de_near_surface.hpp"
#include "check/de_overestimate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace fr {
namespace {

using Field = std::function<double(double, double, double)>;

double sphere(double x, double y, double z) {
  return std::sqrt(x * x + y * y + z * z) - 1;
}

// The exact signed distance to the box [-0.8, 0.8] x [-0.5, 0.5] x [-0.3, 0.3].
double box(double x, double y, double z) {
  const double qx = std::abs(x) - 0.8, qy = std::abs(y) - 0.5, qz = std::abs(z) - 0.3;
  const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0), oz = std::max(qz, 0.0);
  return std::sqrt(ox * ox + oy * oy + oz * oz) + std::min(std::max(qx, std::max(qy, qz)), 0.0);
}

DeBatch batch_of(const Field& f, int* calls = nullptr) {
  return [f, calls](const std::vector<DePoint>& at) {
    if (calls) ++*calls;
    std::vector<float> v;
    for (const DePoint& p : at) v.push_back(float(f(p[0], p[1], p[2])));
    return v;
  };
}

constexpr double kRadius = 2;

// Uniform points in the ball of radius 2 and the field's values there.
struct Samples {
  std::vector<DePoint> points;
  std::vector<float> values;
};
Samples sample(const Field& f, int n = 1500) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-kRadius, kRadius);
  Samples s;
  while (static_cast<int>(s.points.size()) < n) {
    const double x = u(rng), y = u(rng), z = u(rng);
    if (x * x + y * y + z * z > kRadius * kRadius) continue;
    s.points.push_back({float(x), float(y), float(z)});
    s.values.push_back(float(f(x, y, z)));
  }
  return s;
}

DeOverestimate measure(const Field& f) {
  const Samples s = sample(f);
  DeOverestimateOptions o;
  o.max_points = 256;
  return measure_de_overestimate(batch_of(f), s.points, s.values, kRadius, o);
}

TEST(DeOverestimate, TrueDistancesPass) {
  for (const Field& f : {Field(sphere), Field(box)}) {
    const DeOverestimate m = measure(f);
    EXPECT_EQ(m.points_tested, 256u);
    EXPECT_EQ(m.points_over, 0u);
    // The surface threshold (1e-5 R) ends the ray a little before the surface: at most 100/99.
    EXPECT_LE(m.worst_ratio, 100.0 / 99.0);
    EXPECT_GT(m.worst_ratio, 0.9) << "the downhill ray reaches the surface at the ball's edge";
  }
}

TEST(DeOverestimate, ScaledDistancesFailWithTheirFactor) {
  for (double k : {1.25, 1.5, 3.0})
    for (const Field& f : {Field(sphere), Field(box)}) {
      SCOPED_TRACE(k);
      const DeOverestimate m = measure([&](double x, double y, double z) {
        const double d = f(x, y, z);
        return d > 0 ? k * d : d;  // only the outside is scaled: inside is not judged
      });
      EXPECT_GT(m.percent_over(), 95.0);
      EXPECT_GE(m.worst_ratio, 0.995 * k);
      EXPECT_LE(m.worst_ratio, k * 100.0 / 99.0);
      // The reported place: the DE there is k times its true distance, and the surface point
      // found lies on the surface, no farther from p than DE(p).
      const DePoint& p = m.worst_at;
      EXPECT_NEAR(m.worst_de, k * f(p[0], p[1], p[2]), 1e-5 * k);
      const DePoint& s = m.worst_surface_at;
      EXPECT_LT(f(s[0], s[1], s[2]), 1e-5 * kRadius);
      EXPECT_LT(m.worst_surface, m.worst_de);
    }
}

TEST(DeOverestimate, ShortDistancesAreNeverOver) {
  const DeOverestimate m = measure([](double x, double y, double z) {
    return 0.5 * sphere(x, y, z);  // a Mandelbulb-like lower bound
  });
  EXPECT_GT(m.points_tested, 0u);
  EXPECT_EQ(m.points_over, 0u);
  EXPECT_EQ(m.worst_ratio, 0) << "no surface inside any ball";
}

// Too long by 1.6x within 0.05 of the surface, exact beyond: a sampled slope check sees slope
// 1.6 only in that thin shell; the search still finds the near points and the ratio.
TEST(DeOverestimate, OverEstimateOnlyNearTheSurfaceIsFound) {
  const DeOverestimate m = measure([](double x, double y, double z) {
    const double d = sphere(x, y, z);
    return d <= 0 ? d : d < 0.05 ? 1.6 * d : d + 0.03;
  });
  EXPECT_GT(m.points_over, 0u);
  EXPECT_GE(m.worst_ratio, 0.995 * 1.6);
  EXPECT_LE(m.worst_ratio, 1.6 * 100.0 / 99.0);
}

TEST(DeOverestimate, NothingToTestAndDeterministic) {
  int calls = 0;
  const Samples inside = sample([](double, double, double) { return -1.0; });
  const DeOverestimate none =
      measure_de_overestimate(batch_of(sphere, &calls), inside.points, inside.values, kRadius);
  EXPECT_EQ(none.points_tested, 0u);
  EXPECT_EQ(calls, 0) << "no point outside the surface: the DE is not evaluated at all";

  const Samples s = sample(box);
  const DeOverestimate a = measure_de_overestimate(batch_of(box, &calls), s.points, s.values, 2);
  const DeOverestimate b = measure_de_overestimate(batch_of(box), s.points, s.values, 2);
  EXPECT_EQ(calls, 12) << "the gradients, every ray, then ten rounds of bisection";
  EXPECT_EQ(a.worst_ratio, b.worst_ratio);
  EXPECT_EQ(a.worst_at, b.worst_at);
}


// de-near-surface (check/de_near_surface.cpp) on the same exact geometry: true distances pass;
// the true distance multiplied by 1.5 or 3 fails at most points; a DE that is only a quarter of
// the distance never fails; and a DE that is far too short far out but 1.5x too long near the
// surface (the Mandelbox's shape of error, which a search over the whole ball misses) fails.
TEST(DeNearSurface, ExactPassesScaledFails) {
  for (const Field& f : {Field(sphere), Field(box)}) {
    const DeNearSurface exact = measure_de_near_surface(batch_of(f), kRadius);
    EXPECT_GT(exact.surface_points, 100u);
    EXPECT_GT(exact.points_tested, 300u);
    EXPECT_EQ(exact.points_over, 0u) << "worst " << exact.worst_ratio;
    // (A surface point is where the DE drops below the threshold, at most 1/100 of the smallest
    // offset: ratios up to 100/99 for a true distance.)
    EXPECT_LE(exact.worst_ratio, 100.0 / 99 + 1e-4);
    for (double k : {1.5, 3.0}) {
      const Field scaled = [&](double x, double y, double z) { return k * f(x, y, z); };
      const DeNearSurface over = measure_de_near_surface(batch_of(scaled), kRadius);
      EXPECT_GT(over.percent_over(), 50) << "k " << k;
      EXPECT_GE(over.worst_ratio, 0.99 * k) << "k " << k;
      EXPECT_LE(over.worst_ratio, k * 100 / 99 + 1e-4) << "k " << k;
    }
    const Field short_de = [&](double x, double y, double z) { return 0.25 * f(x, y, z); };
    EXPECT_EQ(measure_de_near_surface(batch_of(short_de), kRadius).points_over, 0u);
  }
  // Short by 4x beyond 0.1 of the sphere, 1.5x long within it.
  const Field near_long = [](double x, double y, double z) {
    const double d = sphere(x, y, z);
    return d < 0.1 ? 1.5 * d : 0.25 * d;
  };
  EXPECT_GT(measure_de_near_surface(batch_of(near_long), kRadius).percent_over(), 50);
}
}  // namespace
}  // namespace fr
