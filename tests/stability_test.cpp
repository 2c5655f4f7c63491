// The stability tier (ctest -L stability): stiff and extreme cases, each with an expected answer
// — analytic where one exists (the unit ball, the exact Menger sponge), else the double-precision
// reference render of the same view within a stated tolerance, else the documented result (a
// camera inside the solid is black, one on a surface looking away sees what is in front). Every
// case also checks that no buffer holds a NaN, that no ray spent more than the step budget
// (bounded time), and that every ray's status is one of the four documented ones. The cases, what
// makes each stiff and what was measured, are listed in docs/stability.md.
#include "exact_shapes.hpp"
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/de_probe.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>

namespace fr {
namespace {

using glm::dvec3;
using test::kNone;

// A camera override; what is left out keeps the scene's default camera.
struct View {
  View(std::optional<dvec3> eye_ = {}, std::optional<dvec3> target_ = {},
       std::optional<dvec3> up_ = {}, std::optional<double> fov_deg_ = {})
      : eye(eye_), target(target_), up(up_), fov_deg(fov_deg_) {}
  std::optional<dvec3> eye, target, up;
  std::optional<double> fov_deg;
};

struct Frame {
  FrameImage image;
  CameraRays rays;
  RenderSettings settings;
  SceneState state;
};

using Setup = std::function<void(const SceneInfo&, SceneState&)>;

void set_param(const SceneInfo& info, SceneState& state, const char* key, fr_value v) {
  const int i = info.find_param(key);
  ASSERT_GE(i, 0) << key;
  state.params[i] = v;
}

Frame render_view(const std::string& id, const View& view, RenderSettings settings,
                  const Setup& setup = {}) {
  auto scene =
      id == "unit_ball" ? test::unit_ball()
      : id == "plain_sponge"
          ? test::plain_sponge()
          : test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  Frame f;
  f.state = make_default_state(scene->info);
  if (setup) setup(scene->info, f.state);
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  EXPECT_TRUE(instance && instance->update(f.state, 0, &error)) << error;
  auto put = [](double out[3], dvec3 v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
  };
  if (view.eye) put(f.state.camera.eye, *view.eye);
  if (view.target) put(f.state.camera.target, *view.target);
  if (view.up) put(f.state.camera.up, *view.up);
  if (view.fov_deg) f.state.camera.fov_deg = *view.fov_deg;
  if (settings.width_px == RenderSettings{}.width_px) {
    settings.width_px = 64;
    settings.height_px = 48;
  }
  f.settings = settings;
  f.image = Renderer(test::runtime()).render(scene->info, f.state, settings, true);
  f.rays = make_camera_rays(f.state.camera, settings.width_px, settings.height_px);
  return f;
}

// What every case checks: no NaN anywhere (a miss's depth is +inf by definition, nothing else
// is infinite), no ray over the step budget, only the documented statuses.
void expect_clean(const Frame& f, const std::string& what) {
  size_t bad_colour = 0, bad_depth = 0, bad_factor = 0, over_budget = 0, bad_status = 0;
  for (float v : f.image.linear_rgba) bad_colour += !std::isfinite(v) || v < 0;
  for (float d : f.image.depth) bad_depth += std::isnan(d) || d < 0 || d == -INFINITY;
  for (size_t i = 0; i < f.image.occlusion.size(); ++i)
    bad_factor += !(f.image.occlusion[i] >= 0 && f.image.occlusion[i] <= 1) ||
                  !(f.image.shadow[i] >= 0 && f.image.shadow[i] <= 1);
  for (float s : f.image.steps) over_budget += !(s >= 0 && s <= f.settings.max_steps);
  for (uint8_t s : f.image.ray_status) bad_status += s > 3;
  EXPECT_EQ(bad_colour, 0u) << what << ": NaN, infinite or negative colour";
  EXPECT_EQ(bad_depth, 0u) << what << ": NaN or negative depth";
  EXPECT_EQ(bad_factor, 0u) << what << ": AO or shadow factor outside [0, 1] or NaN";
  EXPECT_EQ(over_budget, 0u) << what << ": a ray spent more than max_steps DE evaluations";
  EXPECT_EQ(bad_status, 0u) << what;
  EXPECT_EQ(f.image.ray_status.size(), f.image.depth.size());
}

double fraction(size_t n, const Frame& f) {
  return double(n) / double(f.image.depth.size());
}

// The unit ball: every pixel against the analytic intersection (render_unit_ball_test explains
// the tolerance: the march may stop up to delta = 2.1 eps outside the sphere, never inside).
void expect_unit_ball(const Frame& f, const std::string& what) {
  const int w = f.image.width_px, h = f.image.height_px;
  int checked = 0, wrong = 0, wrong_mask = 0, behind = 0, early_count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const dvec3 d = f.rays.width_px > 0 ? camera_ray_dir(f.rays, x, y) : dvec3(0);
      double closest = 0;
      const double t = test::sphere_entry(f.rays.eye, d, 1.0, &closest);
      const double t_ref = t == kNone ? glm::length(f.rays.eye) : t;
      const double eps =
          std::max(f.settings.hit_threshold_k * f.rays.pixel_angle_rad * t_ref, 4 * 1.2e-7 * 2);
      if (std::abs(closest - 1) <= 2.5 * eps + 1e-5) continue;  // the rim
      // A ray out of steps is surface only if it came within 4 thresholds of the DE (march.cl),
      // 8 of the distance here (the DE is half the distance): either way within that band.
      if (f.image.ray_status[i] == uint8_t(RayStatus::OutOfSteps) &&
          std::abs(closest - 1) <= 8 * eps + 1e-5)
        continue;
      ++checked;
      const bool hit = std::isfinite(f.image.depth[i]);
      if (hit != (t != kNone)) {
        ++wrong;
        ++wrong_mask;
        continue;
      }
      if (!hit) continue;
      const dvec3 n = glm::normalize(f.rays.eye + t * d);
      const double c = -glm::dot(n, d), delta = 2.1 * eps;
      const double early = t - f.image.depth[i];
      const double allowed = std::sqrt(c * c + 2 * delta + delta * delta) - c + 1e-5 * t + 1e-6;
      behind += early < -(1e-5 * t + 1e-6);
      early_count += early > allowed;
    }
  wrong += behind + early_count;
  std::printf(
      "[measured] %s: %d of %d pixels checked against the analytic ball off (%d hit/miss, "
      "%d behind, %d too far in front); %zu rays out of steps\n",
      what.c_str(), wrong, checked, wrong_mask, behind, early_count,
      count_rays(f.image).out_of_steps);
  EXPECT_GT(checked, 0) << what;
  EXPECT_EQ(wrong, 0) << what << ": pixels off the analytic ball (of " << checked
                      << "): " << wrong_mask << " hit/miss, " << behind << " behind the surface, "
                      << early_count << " too far in front; rays " << count_rays(f.image).hit
                      << " hit, " << count_rays(f.image).out_of_steps << " out of steps";
}

// The level-n Menger sponge against its exact ray cast: an exact hit is rendered, not behind
// it; a rendered hit lies within delta = 3 eps of the geometry (exact_geometry_test explains).
void expect_menger(const Frame& f, int level, const std::string& what, int allowed_missed = 0) {
  const int w = f.image.width_px, h = f.image.height_px;
  int exact_hits = 0, missed = 0, behind = 0, stray = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const dvec3 d = camera_ray_dir(f.rays, x, y);
      const double t_exact = test::menger_entry(f.rays.eye, d, dvec3(0), 1.0, level, 0.0);
      const bool rendered = std::isfinite(f.image.depth[i]);
      const double t = f.image.depth[i];
      const double slack = 1e-5 * std::max(1.0, glm::length(f.rays.eye));
      exact_hits += t_exact != kNone;
      if (t_exact != kNone && !rendered) ++missed;
      if (t_exact != kNone && rendered && t > t_exact + slack) ++behind;
      if (rendered) {
        const double delta =
            std::max(3 * f.settings.hit_threshold_k * f.rays.pixel_angle_rad * t, 1e-6);
        if (test::menger_entry(f.rays.eye, d, dvec3(0), 1.0, level, delta) == kNone) ++stray;
      }
    }
  std::printf(
      "[measured] %s: %d exact hits; %d missed, %d behind, %d stray; %zu rays out of "
      "steps\n",
      what.c_str(), exact_hits, missed, behind, stray, count_rays(f.image).out_of_steps);
  EXPECT_GT(exact_hits, 0) << what << ": the view should show the sponge";
  EXPECT_EQ(behind, 0) << what << ": pixels behind the exact surface";
  EXPECT_EQ(stray, 0) << what << ": hits where the exact geometry has none";
  EXPECT_LE(missed, allowed_missed) << what << ": exact hits the renderer missed";
}

// Against the double-precision reference of the same view (plain sphere tracing, a budget of
// 2000 steps): at most `mask_tolerance` of pixels differ in hit/miss, and where both hit the
// median depth difference is below `depth_tolerance` hit thresholds (eps = k t pixel angle:
// either march may stop anywhere within eps of the surface).
void expect_matches_double(const std::string& id, const View& view, const RenderSettings& s,
                           const Setup& setup, double mask_tolerance, double depth_tolerance,
                           const std::string& what) {
  const Frame f = render_view(id, view, s, setup);
  expect_clean(f, what);
  RenderSettings ref = s;
  ref.precision = Precision::Double;
  ref.relaxation = 1;
  ref.max_steps = 2000;
  const Frame d = render_view(id, view, ref, setup);
  expect_clean(d, what + " (double reference)");
  size_t mask_diff = 0;
  std::vector<double> relative;
  for (size_t i = 0; i < f.image.depth.size(); ++i) {
    const bool a = std::isfinite(f.image.depth[i]), b = std::isfinite(d.image.depth[i]);
    mask_diff += a != b;
    if (a && b && d.image.depth[i] > 0)
      relative.push_back(std::abs(f.image.depth[i] - d.image.depth[i]) /
                         (s.hit_threshold_k * f.rays.pixel_angle_rad * d.image.depth[i]));
  }
  EXPECT_LE(fraction(mask_diff, f), mask_tolerance) << what << ": hit masks differ";
  double median = 0;
  if (!relative.empty()) {
    std::nth_element(relative.begin(), relative.begin() + relative.size() / 2, relative.end());
    median = relative[relative.size() / 2];
    EXPECT_LE(relative[relative.size() / 2], depth_tolerance)
        << what << ": median depth difference, in thresholds";
  }
  const RayCounts c = count_rays(f.image);
  std::printf(
      "[measured] %s: hit mask differs from double at %.2f%% of pixels, median depth "
      "difference %.3f thresholds; %zu hit, %zu missed, %zu out of steps\n",
      what.c_str(), 100 * fraction(mask_diff, f), median, c.hit, c.miss, c.out_of_steps);
}

Setup params(std::vector<std::pair<const char*, fr_value>> values) {
  return [values](const SceneInfo& info, SceneState& state) {
    for (const auto& [key, v] : values) set_param(info, state, key, v);
  };
}
fr_value num(double v) {
  return fr_value{{v, 0, 0}};
}

RenderSettings float_settings() {
  RenderSettings s;
  s.precision = Precision::Float;
  return s;
}

// --- Mandelbulb: polar axis, singular centre, powers and bailouts at their extremes ----------

// Looking straight down the polar axis, where the trigonometric formula divides by r sin(theta).
TEST(Stability, MandelbulbPolarAxisView) {
  expect_matches_double("mandelbulb", {dvec3(0, 0, 3), dvec3(0), dvec3(0, 1, 0), 40},
                        float_settings(), {}, 0.01, 1.0, "polar axis");
}

// The camera at the Mandelbulb's centre, a singular point of the DE (r = 0): bounded steps, and
// the documented result — the eye is on the surface there (DE 0), every ray hits within a few
// thresholds of the eye or starts inside.
TEST(Stability, MandelbulbCameraAtTheSingularCentre) {
  const Frame f = render_view("mandelbulb", {dvec3(0), dvec3(1, 0.2, 0.1)}, float_settings());
  expect_clean(f, "centre");
  for (size_t i = 0; i < f.image.depth.size(); ++i) {
    ASSERT_TRUE(std::isfinite(f.image.depth[i])) << i;
    EXPECT_LT(f.image.depth[i], 1e-4) << i;
  }
}

// A ray aimed exactly through the centre from outside: stops at the surface, not at the centre.
TEST(Stability, MandelbulbRayThroughTheCentre) {
  expect_matches_double("mandelbulb", {dvec3(2.5, 0, 0), dvec3(0), dvec3(0, 0, 1), 30},
                        float_settings(), {}, 0.01, 1.0, "through the centre");
}

TEST(Stability, MandelbulbLowestPower) {
  expect_matches_double("mandelbulb", {}, float_settings(), params({{"power", num(2)}}), 0.01, 1.0,
                        "power 2");
}

TEST(Stability, MandelbulbHighestPowerLowestBailout) {
  expect_matches_double("mandelbulb", {}, float_settings(),
                        params({{"power", num(16)}, {"bailout", num(1.5)}}), 0.01, 1.0,
                        "power 16, bailout 1.5");
}

// Non-integer powers take the angle path (acos, atan2, pow) instead of de Moivre.
TEST(Stability, MandelbulbNonIntegerPower) {
  expect_matches_double("mandelbulb", {}, float_settings(), params({{"power", num(7.9999)}}), 0.01,
                        1.0, "power 7.9999");
}

// The largest bailout with the most iterations: r^n near float's range (the bound in the DE
// library keeps r below FLT_MAX^(1/n)).
TEST(Stability, MandelbulbMaximumBailoutAndIterations) {
  expect_matches_double("mandelbulb", {}, float_settings(),
                        params({{"power", num(16)}, {"bailout", num(12)}, {"iterations", num(64)}}),
                        0.01, 1.0, "bailout 12, 64 iterations");
}

// --- Menger sponge: exact geometry at extremes ---------------------------------------------

TEST(Stability, MengerMaximumLevel) {
  // Level 8: cubes of 1/6561, far below a pixel; the exact cast still decides every pixel.
  const Frame f = render_view("menger", {}, float_settings(), params({{"iterations", num(8)}}));
  expect_clean(f, "level 8");
  expect_menger(f, 8, "level 8", 64 * 48 / 100);
}

// Grazing: the view skims the sponge's top face at 0.5 degrees.
TEST(Stability, MengerGrazingAngle) {
  const dvec3 eye(3.2, 1.0 + 3.2 * std::tan(0.5 * std::numbers::pi / 180), 0.31);
  const Frame f = render_view("menger", {eye, dvec3(0, 1, 0.3)}, float_settings(),
                              params({{"iterations", num(3)}}));
  expect_clean(f, "grazing");
  expect_menger(f, 3, "grazing", 64 * 48 / 50);
}

// Far cameras: the sponge from 10^3 and 10^6 units with a field of view that frames it. Rays
// start at the bounding sphere (no maximum distance), and near it (the start plane), so float
// keeps its precision at the object.
void expect_far_menger(double distance, const std::string& what) {
  const dvec3 eye = glm::normalize(dvec3(3.3, 2.5, 4.3)) * distance;
  const double fov_deg =
      2 * std::atan(1.9 / distance) * 180 / std::numbers::pi;  // frames the sponge
  const Frame f = render_view("menger", {eye, dvec3(0), dvec3(0, 1, 0), fov_deg}, float_settings(),
                              params({{"iterations", num(3)}}));
  expect_clean(f, what);
  expect_menger(f, 3, what, 64 * 48 / 100);
}

TEST(Stability, MengerFarCamera1e3) {
  expect_far_menger(1e3, "10^3");
}
TEST(Stability, MengerFarCamera1e6) {
  expect_far_menger(1e6, "10^6");
}

// The camera inside the solid: every ray starts inside, is black, and costs one DE evaluation.
TEST(Stability, CameraInsideTheSolid) {
  const Frame f = render_view("menger", {dvec3(0.99, 0.99, 0.99), dvec3(0)}, float_settings());
  expect_clean(f, "inside");
  for (size_t i = 0; i < f.image.depth.size(); ++i) {
    EXPECT_EQ(f.image.ray_status[i], uint8_t(RayStatus::Inside)) << i;
    EXPECT_EQ(f.image.steps[i], 1.0f) << i;
    EXPECT_EQ(f.image.linear_rgba[4 * i], 0.0f) << i;
  }
}

// The camera exactly on the sponge's top face (y = 1 at a solid point). Looking up and away it
// sees the sky; looking down into the face it hits at once.
TEST(Stability, CameraOnASurfaceLookingAway) {
  const Frame f = render_view("menger", {dvec3(0.5, 1.0, 0.5), dvec3(0.5, 3, 0.6), dvec3(0, 0, 1)},
                              float_settings());
  expect_clean(f, "on the surface, looking away");
  EXPECT_EQ(count_rays(f.image).miss, f.image.depth.size()) << "all sky";
}

TEST(Stability, CameraOnASurfaceLookingIn) {
  const Frame f = render_view(
      "menger", {dvec3(0.5, 1.0, 0.5), dvec3(0.5, -3, 0.6), dvec3(0, 0, 1), 30}, float_settings());
  expect_clean(f, "on the surface, looking in");
  for (size_t i = 0; i < f.image.depth.size(); ++i) EXPECT_LT(f.image.depth[i], 1e-4) << i;
}

// --- Sierpinski, Julia, benchmark -------------------------------------------------------------

TEST(Stability, SierpinskiMaximumLevel) {
  expect_matches_double("sierpinski", {}, float_settings(), params({{"iterations", num(16)}}), 0.01,
                        1.0, "level 16");
}

TEST(Stability, SierpinskiFarCamera1e6) {
  // From 10^6 units the double reference and float agree: the start plane keeps float exact.
  const dvec3 eye = glm::normalize(dvec3(2.6, 1.6, 3.2)) * 1e6;
  expect_matches_double(
      "sierpinski",
      {eye, dvec3(0), dvec3(0, 1, 0), 2 * std::atan(1.8 / 1e6) * 180 / std::numbers::pi},
      float_settings(), {}, 0.01, 1.0, "10^6");
}

// c = -1.5 on the real axis: a filled Julia set with no interior (thin, dendrite-like; the
// quaternion set is its rotation about the real axis), where the DE is stiff everywhere.
TEST(Stability, JuliaDegenerateRealConstant) {
  expect_matches_double("julia", {}, float_settings(),
                        params({{"c", fr_value{{-1.5, 0, 0}}}, {"c_w", num(0)}}), 0.02, 1.0,
                        "c = -1.5");
}

// c = 0.25, the cusp of the Mandelbrot set's boundary (parabolic): orbits converge slowly.
TEST(Stability, JuliaBoundaryConstant) {
  expect_matches_double("julia", {}, float_settings(),
                        params({{"c", fr_value{{0.25, 0, 0}}}, {"c_w", num(0)}}), 0.02, 1.0,
                        "c = 0.25");
}

TEST(Stability, BenchmarkSceneAllEffects) {
  expect_matches_double("benchmark", {}, float_settings(), {}, 0.01, 1.0, "benchmark");
}

// --- The unit ball: image sizes, thresholds, relaxation, step budgets, deep zoom ------------

TEST(Stability, OnePixelImage) {
  RenderSettings s = float_settings();
  s.width_px = 1;
  s.height_px = 1;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "1x1");
  // One 40-degree pixel: the threshold is 0.35 t, so the march may stop anywhere between the
  // bounding sphere (radius 2, entered at 1.5) and the ball (at 2.5), never behind it.
  ASSERT_EQ(f.image.ray_status[0], uint8_t(RayStatus::Hit));
  EXPECT_GE(f.image.depth[0], 1.5 - 1e-5);
  EXPECT_LE(f.image.depth[0], 2.5 + 1e-5);
}

TEST(Stability, OddImageSizeWithPartialTiles) {
  RenderSettings s = float_settings();
  s.width_px = 37;
  s.height_px = 23;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "37x23");
  expect_unit_ball(f, "37x23");
}

TEST(Stability, VeryWideImage) {
  RenderSettings s = float_settings();
  s.width_px = 16384;  // the largest side the command line accepts
  s.height_px = 3;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "16384x3");
  expect_unit_ball(f, "16384x3");
}

TEST(Stability, TinyHitThreshold) {
  RenderSettings s = float_settings();
  s.hit_threshold_k = 1e-4f;
  s.max_steps = 400;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "k = 1e-4");
  expect_unit_ball(f, "k = 1e-4");
}

TEST(Stability, HugeHitThreshold) {  // ten times the default
  RenderSettings s = float_settings();
  s.hit_threshold_k = 5;
  s.width_px = 128;
  s.height_px = 96;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "k = 5");
  expect_unit_ball(f, "k = 5");
}

TEST(Stability, MaximumRelaxation) {
  RenderSettings s = float_settings();
  s.relaxation = 1.95f;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "omega 1.95");
  expect_unit_ball(f, "omega 1.95");
}

// One step: no ray can converge, so every ray that enters the bounds is counted as out of
// steps (none is silently a hit), and nothing is NaN.
TEST(Stability, StepBudgetOfOne) {
  RenderSettings s = float_settings();
  s.max_steps = 1;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "1 step");
  const RayCounts c = count_rays(f.image);
  EXPECT_EQ(c.hit, 0u);
  EXPECT_GT(c.out_of_steps, f.image.depth.size() / 4);
}

TEST(Stability, HugeStepBudget) {
  RenderSettings s = float_settings();
  s.max_steps = 10000;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "10000 steps");
  expect_unit_ball(f, "10000 steps");
  EXPECT_EQ(count_rays(f.image).out_of_steps, 0u);
}

// Step-count AO is normalised by a fixed count, not the budget: converged pixels keep their
// occlusion when the budget grows (it changed before the fix).
TEST(Stability, StepCountAoDoesNotDependOnTheBudget) {
  RenderSettings a = float_settings(), b = float_settings();
  b.max_steps = 1000;
  const Frame fa = render_view("mandelbulb", {}, a), fb = render_view("mandelbulb", {}, b);
  int compared = 0;
  for (size_t i = 0; i < fa.image.depth.size(); ++i) {
    if (fa.image.ray_status[i] != uint8_t(RayStatus::Hit) ||
        fb.image.ray_status[i] != uint8_t(RayStatus::Hit))
      continue;
    ++compared;
    EXPECT_EQ(fa.image.occlusion[i], fb.image.occlusion[i]) << i;
  }
  EXPECT_GT(compared, 100);
}

// Deep zoom onto the unit sphere: the eye 1e-3 above the surface at (0.6, 0.8, 0) looking at
// it with a 0.01 degree field of view: pixel footprint 3e-9, below float's 1.2e-7 resolution.
// Double resolves it (analytic answer); auto picks double by itself; float is told apart by
// the renderer's own precision check.
TEST(Stability, DeepZoomDoubleResolves) {
  const dvec3 n(0.6, 0.8, 0), eye = n * (1 + 1e-3);
  const View view{eye, dvec3(0), dvec3(0, 0, 1), 0.01};
  RenderSettings s;
  s.precision = Precision::Double;
  const Frame f = render_view("unit_ball", view, s);
  expect_clean(f, "deep zoom, double");
  expect_unit_ball(f, "deep zoom, double");
  RenderSettings automatic;
  automatic.precision = Precision::Auto;
  EXPECT_EQ(render_view("unit_ball", view, automatic).image.precision, Precision::Double);
}

TEST(Stability, DeepZoomFloatStaysFinite) {
  const dvec3 n(0.6, 0.8, 0), eye = n * (1 + 1e-3);
  const Frame f = render_view("unit_ball", {eye, dvec3(0), dvec3(0, 0, 1), 0.01}, float_settings());
  expect_clean(f, "deep zoom, float");
  EXPECT_GT(count_rays(f.image).hit, f.image.depth.size() / 2) << "the surface fills the view";
}

// The deepest zoom each precision resolves: the eye h above the unit sphere at (0.6, 0.8, 0)
// (no coordinate is a float) looking at it, 64x48 at 90 degrees, so the pixel footprint at the
// surface is about 0.03 h. Resolved means every hit pixel's depth within 2 footprints of the
// analytic one. Measured: float resolves h = 1e-4 (footprint 3.2e-6, 27 float ulps of |p| = 1)
// and fails from h = 1e-5 (2.7 ulps: worst 6 footprints, then 89 at 1e-6); double resolves
// h = 1e-12 (footprint 3.2e-14) and h = 1e-13, and fails at 1e-14 (1.4 double ulps). Auto
// switches to double below 16 float ulps, i.e. between the two.
double worst_zoom_error(double h, Precision p, Precision* used = nullptr) {
  const dvec3 eye = dvec3(0.6, 0.8, 0) * (1 + h);
  RenderSettings s;
  s.precision = p;
  const Frame f = render_view("unit_ball", {eye, dvec3(0), dvec3(0, 0, 1), 90}, s);
  expect_clean(f, "zoom");
  if (used) *used = f.image.precision;
  double worst = 0;
  for (int y = 0; y < f.image.height_px; ++y)
    for (int x = 0; x < f.image.width_px; ++x) {
      const dvec3 d = camera_ray_dir(f.rays, x, y);
      const double t = test::sphere_entry(f.rays.eye, d, 1.0);
      if (t == kNone) continue;
      const double depth = f.image.depth[static_cast<size_t>(y) * f.image.width_px + x];
      worst = std::max(worst, std::abs(depth - t) / (f.rays.pixel_angle_rad * t));
    }
  return worst;
}

TEST(Stability, DeepestZoomEachPrecisionResolves) {
  EXPECT_LT(worst_zoom_error(1e-4, Precision::Float), 2) << "float at 27 ulps";
  EXPECT_GT(worst_zoom_error(1e-5, Precision::Float), 2) << "float at 2.7 ulps: past its limit";
  EXPECT_LT(worst_zoom_error(1e-12, Precision::Double), 2) << "double at footprint 3e-14";
  Precision used = Precision::Float;
  EXPECT_LT(worst_zoom_error(1e-5, Precision::Auto, &used), 2) << "auto";
  EXPECT_EQ(used, Precision::Double);
  EXPECT_LT(worst_zoom_error(1e-2, Precision::Auto, &used), 2);
  EXPECT_EQ(used, Precision::Float) << "auto keeps float where it suffices";
}

// A close-up that looks past the surface beside the eye: the eye 1e-7 from an edge of the
// sponge's central cavity (|x|, |y|, |z| < 1/3 and its tunnels are empty; the solid around the edge
// at y = z = 1/3 lies behind the eye), looking across the cavity. The eye's DE alone asks for
// double; the cone pre-pass, marched in double, puts every primary hit far enough off for float:
// Auto renders in float, and the picture is double's.
TEST(Stability, AutoRendersFloatPastANearbySurface) {
  const double h = 1e-7, third = 1.0 / 3;
  const View view{dvec3(0, third - h, third - h), dvec3(0, -third, -third), dvec3(1, 0, 0), 40};
  RenderSettings automatic;
  automatic.precision = Precision::Auto;
  const Frame f = render_view("plain_sponge", view, automatic);
  expect_clean(f, "auto past a nearby surface");
  ASSERT_GT(count_rays(f.image).hit, f.image.depth.size() / 2) << "the far walls fill the view";
  // What the eye's DE alone chose.
  RenderSettings eye_only = automatic;
  eye_only.cone_prepass = false;
  EXPECT_EQ(resolve_precision(test::runtime(), test::plain_sponge()->info, f.state, eye_only),
            Precision::Double);
  EXPECT_EQ(f.image.precision, Precision::Float);
  // Float resolves every hit: the nearest is at least 16 float ulps of its position wide.
  EXPECT_EQ(pixels_below_resolution(f.image.depth, f.rays, Precision::Float), 0u);
  expect_matches_double("plain_sponge", view, automatic, {}, 0.01, 0.5,
                        "auto past a nearby surface");
  // Without the cone pre-pass there is no bound but the eye's: double.
  EXPECT_EQ(render_view("plain_sponge", view, eye_only).image.precision, Precision::Double);
}

// Nothing in view: the eye 1e-7 above the unit ball, looking away from it. The cone pre-pass
// finds no block that can hit, so float (which has nothing to resolve) is Auto's choice.
TEST(Stability, AutoRendersFloatWhenNothingCanBeHit) {
  const dvec3 n(0.6, 0.8, 0);
  RenderSettings automatic;
  automatic.precision = Precision::Auto;
  const Frame f =
      render_view("unit_ball", {n * (1 + 1e-7), n * 2.0, dvec3(0, 0, 1), 60}, automatic);
  expect_clean(f, "auto looking away");
  EXPECT_EQ(count_rays(f.image).hit, 0u);
  EXPECT_EQ(f.image.precision, Precision::Float);
}

// -cl-fast-relaxed-math (finite-math-only, atan2 as atan(y/x), relaxed trig): the polar-axis
// and origin guards must survive it, on the angle path (non-integer power) and the unit ball.
TEST(Stability, FastMathMandelbulb) {
  RenderSettings s = float_settings();
  s.fast_math = true;
  expect_matches_double("mandelbulb", {dvec3(0, 0.01, 3), dvec3(0), dvec3(0, 1, 0), 50}, s,
                        params({{"power", num(7.5)}}), 0.02, 2.0, "fast math, power 7.5");
}

TEST(Stability, FastMathUnitBall) {
  RenderSettings s = float_settings();
  s.fast_math = true;
  const Frame f = render_view("unit_ball", {}, s);
  expect_clean(f, "fast math");
  expect_unit_ball(f, "fast math");
}

// Denormal inputs: DE probes at points whose coordinates are subnormal floats stay finite, in
// float and double, at both widths (the Mandelbulb's r = 0 guard, the Julia set's |z| floor).
TEST(Stability, DenormalPoints) {
  const std::vector<std::array<float, 3>> points = {
      {1e-40f, 0, 0}, {0, 1e-42f, 1e-39f}, {-1e-44f, 1e-45f, 0}, {1e-38f, 1e-38f, 1e-38f}};
  for (const char* id : {"mandelbulb", "julia", "menger", "sierpinski"}) {
    auto scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) /
                                    (std::string(id) + PLUGIN_SUFFIX));
    const auto values = make_default_state(scene->info).params;
    for (int lanes : {1, 16})
      for (Precision p : {Precision::Float, Precision::Double}) {
        const auto de = probe_de(test::runtime(), scene->info, values, points, lanes, p);
        for (size_t i = 0; i < de.size(); ++i)
          EXPECT_TRUE(std::isfinite(de[i])) << id << " point " << i << " lanes " << lanes;
      }
  }
}

}  // namespace
}  // namespace fr
