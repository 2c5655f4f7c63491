// The Mandelbulb's DE evaluated on the device (the scene's own OpenCL source) against values
// derived by hand, at the numerically awkward points, over its whole parameter range.
#include "plugin/scene_instance.hpp"
#include "render/de_probe.hpp"
#include "test_support.hpp"

#include <cmath>
#include <random>

namespace fr {
namespace {

class MandelbulbDe : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = test::mandelbulb();
    ASSERT_TRUE(scene);
    values = make_default_state(scene->info).params;
  }
  void set(const char* key, double v) { values[scene->info.find_param(key)].v[0] = v; }
  std::vector<float> probe(const std::vector<std::array<float, 3>>& points, int lanes = 16,
                           Precision precision = Precision::Float) {
    return probe_de(test::runtime(), scene->info, values, points, lanes, precision);
  }
  std::shared_ptr<const LoadedScene> scene;
  std::vector<fr_value> values;
};

std::vector<std::array<float, 3>> awkward_points() {
  std::vector<std::array<float, 3>> pts = {{0, 0, 0}, {1e-30f, 0, 0}, {0, 0, 1e-30f}};
  for (float z = -3; z <= 3; z += 0.25f) pts.push_back({0, 0, z});          // the polar axis
  for (float z = -2; z <= 2; z += 0.5f) pts.push_back({1e-7f, -1e-7f, z});  // next to it
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-3, 3);
  for (int i = 0; i < 300; ++i) pts.push_back({u(rng), u(rng), u(rng)});
  return pts;
}

// Finite everywhere — origin, polar axis, far away — at the extremes of every parameter.
TEST_F(MandelbulbDe, FiniteOverParameterRange) {
  const auto pts = awkward_points();
  struct Case {
    double power, bailout, iterations;
  };
  for (Case c : {Case{2, 12, 64}, Case{16, 12, 64}, Case{16, 1.5, 1}, Case{8, 2, 8}}) {
    set("power", c.power);
    set("bailout", c.bailout);
    set("iterations", c.iterations);
    const auto de = probe(pts);
    for (size_t i = 0; i < pts.size(); ++i)
      ASSERT_TRUE(std::isfinite(de[i]))
          << "power " << c.power << " bailout " << c.bailout << " iterations " << c.iterations
          << " at (" << pts[i][0] << "," << pts[i][1] << "," << pts[i][2] << "): " << de[i];
  }
}

// One iteration from p = (x, 0, 0), power 8: r = x, theta = pi/2, phi = 0, so
// z1 = x^8 (sin 4pi, 0, cos 4pi) + p = (x, 0, x^8), dr1 = 8 x^7 + 1, DE = 0.5 r1 ln r1 / dr1.
TEST_F(MandelbulbDe, OneIterationByHand) {
  set("iterations", 1);
  std::vector<std::array<float, 3>> pts;
  std::vector<double> expected;
  for (double x : {0.6, 1.1, 1.5, 1.9}) {
    pts.push_back({static_cast<float>(x), 0, 0});
    const double r1 = std::sqrt(x * x + std::pow(x, 16));
    expected.push_back(0.5 * r1 * std::log(r1) / (8 * std::pow(x, 7) + 1));
  }
  for (int lanes : {1, 16})
    for (Precision p : {Precision::Float, Precision::Double}) {
      const auto de = probe(pts, lanes, p);
      for (size_t i = 0; i < pts.size(); ++i)
        EXPECT_NEAR(de[i], expected[i], 2e-5 * std::abs(expected[i]) + 1e-6)
            << "x = " << pts[i][0] << " lanes " << lanes
            << (p == Precision::Double ? " double" : " float");
    }
}

TEST_F(MandelbulbDe, LaneWidthsAgree) {
  const auto pts = awkward_points();
  const auto one = probe(pts, 1), sixteen = probe(pts, 16), eight = probe(pts, 8);
  for (size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(sixteen[i], one[i], 1e-5f * std::abs(one[i]) + 1e-6f) << i;
    EXPECT_NEAR(eight[i], one[i], 1e-5f * std::abs(one[i]) + 1e-6f) << i;
  }
}

// Lane widths on scenes without mirror symmetry, at points off every coordinate plane. The
// Mandelbulb is mirror-symmetric in x and y, so a lane that flips the sign of y computes the
// same DE there and no Mandelbulb point can catch it; the Julia set with the default c and the
// benchmark scene (objects at asymmetric places) have no such symmetry. The test first shows
// that a sign flip of any axis changes the DE at a quarter or more of its points (so a lane with
// that error would fail), then compares widths 8 and 16 with width 1 at every point. Mutation
// caught: negating y in lane 5 of the probe's packet (probe.cl) fails 31 points per scene at width
// 16 and 58 at width 8 (the Mandelbulb-only test above passed with it).
TEST(LaneWidths, AgreeOnAsymmetricScenesOffEverySymmetryPlane) {
  struct SceneBox {
    const char* id;
    std::array<float, 3> lo, hi;
  };
  for (const SceneBox& box : {SceneBox{"julia", {-1.2f, -1.2f, -1.2f}, {1.2f, 1.2f, 1.2f}},
                              SceneBox{"benchmark", {-3, -1.2f, -2.2f}, {3.6f, 1.4f, 2.2f}}}) {
    auto scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) /
                                    (std::string(box.id) + PLUGIN_SUFFIX));
    ASSERT_TRUE(scene);
    const auto values = make_default_state(scene->info).params;
    std::mt19937 rng(3);
    std::vector<std::array<float, 3>> pts;
    while (pts.size() < 512) {
      std::array<float, 3> q;
      for (int a = 0; a < 3; ++a)
        q[a] = std::uniform_real_distribution<float>(box.lo[a], box.hi[a])(rng);
      if (std::abs(q[0]) < 0.05f || std::abs(q[1]) < 0.05f || std::abs(q[2]) < 0.05f) continue;
      pts.push_back(q);
    }
    auto probe = [&](const std::vector<std::array<float, 3>>& at, int lanes) {
      return probe_de(test::runtime(), scene->info, values, at, lanes);
    };
    const auto one = probe(pts, 1);
    auto tolerance = [](float v) { return 1e-5f * std::abs(v) + 1e-6f; };
    for (int axis = 0; axis < 3; ++axis) {
      auto mirrored = pts;
      for (auto& q : mirrored) q[axis] = -q[axis];
      const auto m = probe(mirrored, 1);
      int sensitive = 0;
      for (size_t i = 0; i < pts.size(); ++i)
        sensitive += std::abs(m[i] - one[i]) > 10 * tolerance(one[i]);
      EXPECT_GT(sensitive, 128) << box.id << ": a sign error in axis " << axis
                                << " would pass at most points";
    }
    for (int lanes : {8, 16}) {
      const auto wide = probe(pts, lanes);
      for (size_t i = 0; i < pts.size(); ++i)
        EXPECT_NEAR(wide[i], one[i], tolerance(one[i]))
            << box.id << " width " << lanes << " lane " << i % lanes << " at (" << pts[i][0] << ", "
            << pts[i][1] << ", " << pts[i][2] << ")";
    }
  }
}

// The textbook formula in double on the host: the angles through acos and atan2, r^n through
// pow. An independent reference for both device paths (de Moivre for whole powers, the angles
// for fractional ones).
double reference_de(double px, double py, double pz, double power, double bailout, int iterations) {
  double x = px, y = py, z = pz, dr = 1;
  double r = std::sqrt(x * x + y * y + z * z);
  for (int i = 0; i < iterations && r < bailout; ++i) {
    const double theta = std::acos(z / r) * power, phi = std::atan2(y, x) * power;
    const double zr = std::pow(r, power);
    dr = power * std::pow(r, power - 1) * dr + 1;
    x = zr * std::sin(theta) * std::cos(phi) + px;
    y = zr * std::sin(theta) * std::sin(phi) + py;
    z = zr * std::cos(theta) + pz;
    r = std::sqrt(x * x + y * y + z * z);
  }
  return 0.5 * std::log(r) * r / dr;
}

// Whole powers take the trigonometry-free path and fractional ones the angles; both must be the
// textbook formula. In double on the device the only differences left are rounding, amplified by
// the orbit's sensitivity, so a tight tolerance holds at points off the polar axis.
// 400 points in the cube around the bulb, where the textbook formula is compared.
std::vector<std::array<float, 3>> textbook_points() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.3f, 1.3f);
  std::vector<std::array<float, 3>> pts;
  for (int i = 0; i < 400; ++i) pts.push_back({u(rng), u(rng), u(rng)});
  return pts;
}

TEST_F(MandelbulbDe, MatchesTextbookFormulaForWholeAndFractionalPowers) {
  const auto pts = textbook_points();
  set("bailout", 2);
  set("iterations", 6);
  for (double power : {2.0, 3.0, 8.0, 16.0, 2.5, 7.25}) {
    set("power", power);
    const auto de = probe(pts, 16, Precision::Double);
    int checked = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
      const double expected = reference_de(pts[i][0], pts[i][1], pts[i][2], power, 2, 6);
      EXPECT_NEAR(de[i], expected, 1e-5 * std::abs(expected) + 1e-7)
          << "power " << power << " at (" << pts[i][0] << "," << pts[i][1] << "," << pts[i][2]
          << ")";
      checked += std::abs(expected) < 0.05;
    }
    EXPECT_GT(checked, 10) << "power " << power << ": too few points near the surface";
  }
}

// The float build against the same double textbook reference at the same 400 points, at both
// widths: what float costs, stated as a tolerance (1e-3 relative + 1e-5; the worst point
// measured 0.18 of it).
// Mutation caught: dropping the "+ 1" of the derivative's update (dr = n r^(n-1) dr) fails at
// most points.
TEST_F(MandelbulbDe, FloatMatchesTextbookFormula) {
  const auto pts = textbook_points();
  set("bailout", 2);
  set("iterations", 6);
  double worst = 0;
  for (double power : {2.0, 3.0, 8.0, 16.0, 2.5, 7.25})
    for (int lanes : {1, 16}) {
      set("power", power);
      const auto de = probe(pts, lanes, Precision::Float);
      for (size_t i = 0; i < pts.size(); ++i) {
        const double expected = reference_de(pts[i][0], pts[i][1], pts[i][2], power, 2, 6);
        const double error = std::abs(de[i] - expected) / (1e-3 * std::abs(expected) + 1e-5);
        worst = std::max(worst, error);
        EXPECT_LE(error, 1.0) << "power " << power << " width " << lanes << " at (" << pts[i][0]
                              << "," << pts[i][1] << "," << pts[i][2] << "): " << de[i] << " vs "
                              << expected;
      }
    }
  RecordProperty("worst_error_fraction_of_tolerance", std::to_string(worst));
}

// The bound, derived here rather than copied from the plugin: with R = 2^(1/(n-1)), a point c
// with |c| > R escapes, since while |z| >= |c| > R, |z^n + c| >= |z|^n - |c| >= |z| (|z|^(n-1) - 1)
// and |z|^(n-1) - 1 > 1, so |z| grows geometrically from z1 = c. So the set lies in |p| <= R, and
// the bounding radius must be at least R; at most 10% (+0.05) more, or the march wastes steps.
// Outside the set the DE is positive: on the sphere |p| = bounding radius every point escapes.
TEST_F(MandelbulbDe, BoundingSphereIsOutsideTheSet) {
  std::mt19937 rng(11);
  std::normal_distribution<float> g;
  for (double power : {2.0, 3.0, 8.0, 16.0}) {
    set("power", power);
    std::string error;
    auto instance = SceneInstance::create(scene, &error);
    SceneState state = make_default_state(scene->info);
    state.params = values;
    ASSERT_TRUE(instance->update(state, 0, &error)) << error;
    const double escape_radius = std::pow(2.0, 1.0 / (power - 1));
    EXPECT_GE(state.bounding_radius, escape_radius) << "power " << power;
    EXPECT_LE(state.bounding_radius, 1.1 * escape_radius + 0.05) << "power " << power;
    std::vector<std::array<float, 3>> pts;
    for (int i = 0; i < 200; ++i) {
      float x = g(rng), y = g(rng), z = g(rng);
      const float s = static_cast<float>(state.bounding_radius) / std::sqrt(x * x + y * y + z * z);
      pts.push_back({x * s, y * s, z * s});
    }
    const auto de = probe(pts);
    for (size_t i = 0; i < pts.size(); ++i)
      EXPECT_GT(de[i], 0.0f) << "power " << power << " point " << i;
  }
}

// Animation is a function of time only: centre + depth * sin(2 pi speed t).
TEST_F(MandelbulbDe, AnimatedPowerFollowsTime) {
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  SceneState state = make_default_state(scene->info);
  const int power = scene->info.find_param("power");
  ASSERT_TRUE(instance->update(state, 1.25, &error));
  EXPECT_EQ(state.params[power].v[0], 8.0) << "animation is off by default";
  state.params[scene->info.find_param("animate_power")].v[0] = 1;
  ASSERT_TRUE(instance->update(state, 1.25, &error));
  // speed 0.1, t = 1.25: sin(2 pi * 0.125) = sin(pi/4).
  EXPECT_NEAR(state.params[power].v[0], 8 + 2 * std::sqrt(0.5), 1e-12);
  ASSERT_TRUE(instance->update(state, 7.0, &error));
  ASSERT_TRUE(instance->update(state, 1.25, &error));
  EXPECT_NEAR(state.params[power].v[0], 8 + 2 * std::sqrt(0.5), 1e-12) << "same time, same state";
}

}  // namespace
}  // namespace fr
