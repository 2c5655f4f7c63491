// Deep zoom end to end (render.precision "dd", docs/deep_zoom.md): views 1e-19 from the
// Mandelbox's and the Menger sponge's surfaces, rendered by the in-tree scenes in pairs, against a
// host tracer in __float128 (tests/float128_reference.hpp, no code shared with the kernels) along
// the same rays: the same pixels hit, at the same depths to a fraction of a pixel's footprint. The
// same views in double are shown to be wrong (why pairs are needed), and automatic precision is
// shown to pick float, double and double-double where each must.
#include "float128_reference.hpp"
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/de_probe.hpp"
#include "render/depth_iterations.hpp"
#include "render/kernel_assembly.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace fr {
namespace {

using test::quad;
using test::quad_sqrt;

struct Scene {
  std::shared_ptr<const LoadedScene> scene;
  SceneState state;
};

// Scene `id` with the parameters' first components set as given (a choice by its index).
Scene load_scene(const std::string& id,
                 const std::vector<std::pair<std::string, double>>& values) {
  Scene s;
  s.scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  s.state = make_default_state(s.scene->info);
  for (const auto& [param, value] : values) {
    const int index = s.scene->info.find_param(param);
    EXPECT_GE(index, 0) << param;
    if (index >= 0) s.state.params[index].v[0] = value;
  }
  std::string error;
  auto instance = SceneInstance::create(s.scene, &error);
  EXPECT_TRUE(instance && instance->update(s.state, 0.0, &error)) << error;
  return s;
}

Scene load_scene(const std::string& id, const std::string& param, double value) {
  return load_scene(id, {{param, value}});
}

// Sphere tracing in __float128 from `from` along unit `dir` until the reference estimate is below
// `stop`: the distance, or -1 where the ray leaves (past t_max) or stalls.
template <class Shape>
quad trace(const Shape& shape, const quad from[3], const quad dir[3], quad stop, quad t_max) {
  quad t = 0;
  for (int step = 0; step < 4000; ++step) {
    const quad p[3] = {from[0] + t * dir[0], from[1] + t * dir[1], from[2] + t * dir[2]};
    const quad de = shape.de(p);
    if (de < stop) return t;
    t += de;
    if (t > t_max) return -1;
  }
  return -1;
}

// The renderer's march (kernels/march.cl) written again in __float128, for a ray from an eye
// outside the surface with relaxation off: plain steps of the estimate until it falls below the
// hit threshold k t (pixel angle), then `refine` more plain steps. The distance, or -1 where the
// ray runs out of steps or leaves (past t_max). Where the estimate is a loose lower bound (the
// Mandelbox's is some ten times short near its surface) this stops well before the surface, as
// the renderer does: the comparison is of the same algorithm in more precision.
template <class Shape>
quad march_like_renderer(const Shape& shape, const quad from[3], const quad dir[3],
                         quad threshold_per_t, int max_steps, int refine, quad t_max) {
  quad t = 0;
  const auto de_at = [&](quad at) {
    const quad p[3] = {from[0] + at * dir[0], from[1] + at * dir[1], from[2] + at * dir[2]};
    return shape.de(p);
  };
  for (int step = 0; step < max_steps; ++step) {
    const quad de = de_at(t);
    if (de < threshold_per_t * t) {
      for (int i = 0; i < refine; ++i) t += std::max(de_at(t), quad(0));
      return t;
    }
    t += de;
    if (t > t_max) return -1;
  }
  return -1;
}

// Puts the camera `distance` in front of where the ray from `start` towards `aim` meets the
// shape's surface, looking along the ray: eye and target as pairs.
template <class Shape>
void place_deep_camera(const Shape& shape, const double start[3], const double aim[3],
                       quad distance, SceneState& state, quad eye[3]) {
  quad dir[3], from[3], length2 = 0;
  for (int c = 0; c < 3; ++c) {
    from[c] = start[c];
    dir[c] = quad(aim[c]) - start[c];
    length2 += dir[c] * dir[c];
  }
  for (quad& c : dir) c /= quad_sqrt(length2);
  const quad t = trace(shape, from, dir, 1e-26, 30);
  ASSERT_GT(t, 0) << "the aiming ray found no surface";
  for (int c = 0; c < 3; ++c) {
    eye[c] = from[c] + (t - distance) * dir[c];
    test::split(eye[c], &state.camera.eye[c], &state.camera_lo.eye[c]);
    test::split(eye[c] + dir[c], &state.camera.target[c], &state.camera_lo.target[c]);
  }
  state.camera.fov_deg = 60;
}

RenderSettings depth_settings(Precision precision) {
  RenderSettings s;
  s.width_px = 16;
  s.height_px = 12;
  s.precision = precision;
  s.samples = 1;
  s.disabled_stages = all_optional_stages();  // the depth is what is compared
  s.max_steps = 400;
  s.relaxation = 1;  // plain sphere tracing, as the reference marches
  s.refine_steps = 2;
  return s;
}

struct DepthComparison {
  int both_hit = 0, mask_differs = 0, reference_out_of_steps = 0;
  std::vector<double> footprints;  // |depth - reference| over the pixel's footprint, where both hit
  double median() const {
    std::vector<double> v = footprints;
    std::sort(v.begin(), v.end());
    return v.empty() ? 1e30 : v[v.size() / 2];
  }
  double share_within(double limit) const {
    const auto n =
        std::count_if(footprints.begin(), footprints.end(), [&](double f) { return f <= limit; });
    return footprints.empty() ? 0 : double(n) / double(footprints.size());
  }
};

// The rendered depths (from the eye) against the reference tracer from the eye's pairs along each
// pixel's ray (the renderer's own camera model in double: directions are not what pairs are for).
template <class Shape>
DepthComparison compare_depths(const Shape& shape, const Scene& s, const quad eye[3],
                               const FrameImage& image, const RenderSettings& settings) {
  const std::array<double, 3> view = view_vector(s.state.camera, s.state.camera_lo);
  fr_camera relative = s.state.camera;
  for (int c = 0; c < 3; ++c) {
    relative.eye[c] = 0;
    relative.target[c] = view[c];
  }
  const CameraRays rays = make_camera_rays(relative, settings.width_px, settings.height_px);
  DepthComparison out;
  for (int y = 0; y < settings.height_px; ++y)
    for (int x = 0; x < settings.width_px; ++x) {
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      const quad dir[3] = {d.x, d.y, d.z};
      const float depth = image.depth[static_cast<size_t>(y) * settings.width_px + x];
      const quad t = march_like_renderer(
          shape, eye, dir,
          quad(settings.hit_threshold_k) * static_cast<float>(rays.pixel_angle_rad),
          settings.max_steps, settings.refine_steps, 1.0);
      if (t < 0 && trace(shape, eye, dir, 1e-25, 1.0) > 0) {
        ++out.reference_out_of_steps;  // the renderer's fallback for such rays is its own
        continue;
      }
      const bool hit = std::isfinite(depth), reference_hit = t > 0;
      if (hit != reference_hit) {
        std::printf("pixel %d,%d: depth %g, the reference's %g\n", x, y, double(depth),
                    static_cast<double>(t));
        ++out.mask_differs;
        continue;
      }
      if (!hit) continue;
      ++out.both_hit;
      const double footprint = static_cast<double>(t) * rays.pixel_angle_rad;
      out.footprints.push_back(std::abs(double(depth) - static_cast<double>(t)) / footprint);
    }
  return out;
}

template <class Shape>
void expect_deep_view_right(const Shape& shape, const Scene& s, const quad eye[3]) {
  Renderer renderer(test::runtime());
  const RenderSettings pairs = depth_settings(Precision::DoubleDouble);
  const FrameImage image = renderer.render(s.scene->info, s.state, pairs, true);
  EXPECT_EQ(image.precision, Precision::DoubleDouble);
  // The stability tier's invariants: nothing NaN, every ray's status a documented one.
  for (float v : image.linear_rgba) ASSERT_FALSE(std::isnan(v)) << "a NaN in the picture";
  for (float v : image.depth) ASSERT_FALSE(std::isnan(v)) << "a NaN depth";
  for (uint8_t v : image.ray_status) ASSERT_LE(v, 3) << "an undocumented ray status";
  const DepthComparison got = compare_depths(shape, s, eye, image, pairs);
  // Every pixel looks at the surface 1e-19 away. The two marches take the same steps but for
  // the roundings (the pairs' estimate is within a thousandth of a footprint of the reference's),
  // so they stop at the same step; now and then a ray whose estimate meets the threshold within
  // that margin stops one step apart (at most a footprint or so).
  std::printf(
      "pairs: %d pixels hit in both, %d differ, median %.3g footprints, %.0f%% within "
      "0.1\n",
      got.both_hit, got.mask_differs, got.median(), 100 * got.share_within(0.1));
  EXPECT_GE(got.both_hit, pairs.width_px * pairs.height_px * 9 / 10);
  EXPECT_LE(got.mask_differs, 1);
  EXPECT_LE(got.median(), 0.01) << "median depth difference, in footprints";
  EXPECT_GE(got.share_within(0.1), 0.95) << "share within a tenth of a footprint";

  // Double cannot hold the eye (an ulp of it is some 8e-16, thousands of times the view's size):
  // its picture is of somewhere else.
  const RenderSettings doubles = depth_settings(Precision::Double);
  const FrameImage wrong = renderer.render(s.scene->info, s.state, doubles, true);
  const DepthComparison bad = compare_depths(shape, s, eye, wrong, doubles);
  std::printf(
      "double: %d pixels hit in both, %d differ, median %.3g footprints, %.0f%% within "
      "1\n",
      bad.both_hit, bad.mask_differs, bad.median(), 100 * bad.share_within(1));
  EXPECT_LT(bad.share_within(1), 0.5) << "double drew the view as well as pairs did";
}

// A view `distance` from where the ray from `start` towards `aim` meets the surface of scene `id`
// (its `iterations` set), rendered in pairs against the march in __float128 with `shape`.
template <class Shape>
void expect_right_at(Scene s, const Shape& shape, const double start[3], const double aim[3],
                     quad distance) {
  if (!test::runtime().device().has_fp64) GTEST_SKIP() << "the device has no double precision";
  quad eye[3];
  place_deep_camera(shape, start, aim, distance, s.state, eye);
  expect_deep_view_right(shape, s, eye);
}

// Lowe's Mandelbox (scale 2; 90 iterations resolve 2^-90, 8e-28) seen from 1e-19 above its
// surface; and, for the stability tier, from 1e-18 and 1e-22 (a footprint of 8e-24, 2^-77).
const double kBoxStart[3] = {7, 6.5, 5}, kBoxAim[3] = {2, 1.3, 0.7};
TEST(DeepZoom, MandelboxAt1e19MatchesFloat128Tracer) {
  expect_right_at(load_scene("mandelbox", "iterations", 90), test::BoxReference{}, kBoxStart, kBoxAim, 1e-19);
}
TEST(DeepZoom, MandelboxAt1e18MatchesFloat128Tracer) {
  expect_right_at(load_scene("mandelbox", "iterations", 90), test::BoxReference{}, kBoxStart, kBoxAim, 1e-18);
}
TEST(DeepZoom, MandelboxAt1e22MatchesFloat128Tracer) {
  expect_right_at(load_scene("mandelbox", "iterations", 90), test::BoxReference{}, kBoxStart, kBoxAim, 1e-22);
}

// Iterations that follow the depth (render.auto_iterations, render/depth_iterations.hpp): the box
// with its default 14, 1e-19 from its surface, is raised to what the view's footprint needs
// (log2(R / f), some 71 here), and the view rendered with that count matches the reference
// with the same count.
TEST(DeepZoom, MandelboxIterationsFollowTheDepth) {
  if (!test::runtime().device().has_fp64) GTEST_SKIP() << "the device has no double precision";
  Scene s = load_scene("mandelbox", "iterations", 14);
  test::BoxReference box;
  quad eye[3];
  place_deep_camera(box, kBoxStart, kBoxAim, 1e-19, s.state, eye);
  const RenderSettings pairs = depth_settings(Precision::DoubleDouble);
  const DeProbe probe = [&](const std::vector<fr_value>& params,
                            const std::vector<std::array<float, 3>>& points, Precision precision,
                            const PairOrigin* origin) {
    return probe_de(test::runtime(), s.scene->info, params, points, 1, precision, origin);
  };
  std::vector<fr_value> params;
  const auto raised = raise_iterations_for_view(probe, s.scene->info, s.state, pairs.width_px,
                                                pairs.height_px, true, params);
  ASSERT_EQ(raised.size(), 1u);
  std::printf("raised: %s\n", describe_raised(raised).c_str());
  EXPECT_EQ(raised[0].set, 14);
  EXPECT_GE(raised[0].used, 64);
  EXPECT_LE(raised[0].used, 88);
  s.state.params = params;
  box.iterations = raised[0].used;
  expect_deep_view_right(box, s, eye);
}

// The Mandelbox's Julia form (the scene's defaults: scale -2, min radius 0.3, c = 1.8 in each
// coordinate; a double kernel gets a parameter's double whole) and the rotated box (the scene's default turns, 6 degrees about x and 11 about y) from 1e-19
// above their surfaces.
TEST(DeepZoom, MandelboxJuliaAt1e19MatchesFloat128Tracer) {
  test::BoxReference julia;
  julia.scale = -2;
  julia.min_radius = 0.3;
  julia.julia = true;
  for (double& c : julia.c) c = 1.8;
  const double start[3] = {5.5, 4, 6.4}, aim[3] = {0.3, 0.2, 0.1};
  expect_right_at(load_scene("mandelbox_julia", "iterations", 90), julia, start, aim, 1e-19);
}
TEST(DeepZoom, MandelboxRotatedAt1e19MatchesFloat128Tracer) {
  test::BoxReference rotated;
  rotated.angle_rad[0] = 6.0 * (M_PI / 180);
  rotated.angle_rad[1] = 11.0 * (M_PI / 180);
  const double start[3] = {10, 7, 11}, aim[3] = {0.5, 0.3, 0.2};
  expect_right_at(load_scene("mandelbox_rotated", "iterations", 90), rotated, start, aim, 1e-19);
}

// The hybrid composer's steps in pairs, chained as Lowe's box (box fold, sphere fold, scale 2 and
// add p; no safety factor, the linear estimate) with its bailout 1000: the Mandelbox's reference
// with that bailout, from 1e-19 above the surface.
TEST(DeepZoom, HybridBoxStepsAt1e19MatchFloat128Tracer) {
  test::BoxReference box;
  box.bailout2 = 1e6;
  // Kinds and estimates by index (plugins/hybrid/hybrid.c): none 0, box_fold 2, sphere_fold 3,
  // scale_translate 4; linear 1.
  const Scene s = load_scene(
      "hybrid", {{"step1", 2}, {"step1_a", 1}, {"step2", 3}, {"step2_a", 0.5}, {"step2_b", 1},
                 {"step3", 4}, {"step3_a", 2}, {"step4", 0}, {"step5", 0}, {"step6", 0},
                 {"iterations", 90}, {"bailout", 1000}, {"estimate", 1}, {"de_factor", 1},
                 {"bound", 15}});
  expect_right_at(s, box, kBoxStart, kBoxAim, 1e-19);
}

// The Menger sponge (level 50: holes down to 3^-50, 1.4e-24) from 1e-19 above a face.
TEST(DeepZoom, MengerAt1e19MatchesFloat128Tracer) {
  const double start[3] = {2.1, 1.7, 2.6}, aim[3] = {0.13, 0.31, -0.05};
  expect_right_at(load_scene("menger", "iterations", 50), test::SpongeReference{}, start, aim, 1e-19);
}

// The Mandelbulb (power 8, 40 iterations) from 1e-19 above its surface: the pairs' de Moivre
// form against the reference's trigonometry in __float128.
TEST(DeepZoom, MandelbulbAt1e19MatchesFloat128Tracer) {
  const double start[3] = {0.3, 0.7, 2.2}, aim[3] = {0.02, 0.05, 0};
  expect_right_at(load_scene("mandelbulb", "iterations", 40), test::BulbReference{}, start, aim, 1e-19);
}

// A pair estimate that is double at some parameters is found out, not trusted: the Mandelbulb at
// power 8.5 has no pair form (its angles would need trigonometry in pairs), so 1e-19 above its
// surface the host's probe sees it round (pair_estimate_resolves_view) and auto stays in double
// (where render warns); at power 8 the same test passes and auto picks pairs.
TEST(DeepZoom, PairEstimateThatRoundsToDoubleIsFoundOut) {
  if (!test::runtime().device().has_fp64) GTEST_SKIP() << "the device has no double precision";
  const double start[3] = {0.3, 0.7, 2.2}, aim[3] = {0.02, 0.05, 0};
  RenderSettings settings = depth_settings(Precision::Auto);
  settings.width_px = 320;
  settings.height_px = 240;
  for (const double power : {8.5, 8.0}) {
    SCOPED_TRACE("power " + std::to_string(power));
    Scene s = load_scene("mandelbulb", {{"iterations", 40}, {"power", power}});
    test::BulbReference bulb;
    bulb.power = power;
    quad eye[3];
    place_deep_camera(bulb, start, aim, 1e-19, s.state, eye);
    const PairProbe probe = [&](const std::vector<std::array<float, 3>>& points,
                                const PairOrigin& origin) {
      return probe_de(test::runtime(), s.scene->info, s.state.params, points, 1,
                      Precision::DoubleDouble, &origin);
    };
    const CameraRays rays = view_camera_rays(s.state, settings.width_px, settings.height_px);
    const bool whole = power == 8.0;
    EXPECT_EQ(pair_estimate_resolves_view(probe, s.state, rays), whole);
    EXPECT_EQ(resolve_precision(test::runtime(), s.scene->info, s.state, settings),
              whole ? Precision::DoubleDouble : Precision::Double);
  }
}

// Automatic precision: float at the scene's own view, double 1e-10 from the surface (a footprint
// of 3.6e-13 at 320 pixels, some 150 ulps of the bounding radius 10.7), pairs 1e-19 from it; and
// double for a scene without a pair estimate, with the eye and target that double cannot tell
// apart refused by name rather than drawn.
TEST(DeepZoom, AutoPicksFloatDoubleAndPairsByDepth) {
  if (!test::runtime().device().has_fp64) GTEST_SKIP() << "the device has no double precision";
  Scene s = load_scene("mandelbox", "iterations", 90);
  RenderSettings settings = depth_settings(Precision::Auto);
  settings.width_px = 320;
  settings.height_px = 240;
  EXPECT_EQ(resolve_precision(test::runtime(), s.scene->info, s.state, settings), Precision::Float);
  test::BoxReference box;
  quad eye[3];
  place_deep_camera(box, kBoxStart, kBoxAim, 1e-10, s.state, eye);
  EXPECT_EQ(resolve_precision(test::runtime(), s.scene->info, s.state, settings),
            Precision::Double);
  place_deep_camera(box, kBoxStart, kBoxAim, 1e-19, s.state, eye);
  EXPECT_EQ(resolve_precision(test::runtime(), s.scene->info, s.state, settings),
            Precision::DoubleDouble);

  // The unit ball has no pair estimate: 1e-19 above it, double (and a warning, by render).
  Scene ball;
  ball.scene = test::unit_ball();
  ball.state = make_default_state(ball.scene->info);
  EXPECT_FALSE(has_pair_estimate(ball.scene->info));
  const double hi = 1, lo = 1e-19;
  ball.state.camera.eye[0] = hi;
  ball.state.camera_lo.eye[0] = lo;
  ball.state.camera.eye[1] = ball.state.camera.eye[2] = 0;
  ball.state.camera.target[0] = ball.state.camera.target[1] = ball.state.camera.target[2] = 0;
  EXPECT_EQ(resolve_precision(test::runtime(), ball.scene->info, ball.state, settings),
            Precision::Double);
  // Eye and target 1e-30 apart: the same double.
  for (int c = 0; c < 3; ++c) ball.state.camera.target[c] = ball.state.camera.eye[c];
  ball.state.camera_lo.target[0] = lo + 1e-30;
  ASSERT_FALSE(check_camera(ball.state.camera, ball.state.camera_lo));
  Scene& bulb = ball;
  Renderer renderer(test::runtime());
  try {
    renderer.render(bulb.scene->info, bulb.state, settings, true);
    ADD_FAILURE() << "rendered a view double cannot tell from a point";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("closer than double tells apart"), std::string::npos)
        << e.what();
  }
  settings.precision = Precision::DoubleDouble;
  try {
    renderer.render(bulb.scene->info, bulb.state, settings, true);
    ADD_FAILURE() << "rendered pairs for a scene without a pair estimate";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no pair estimate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fr
