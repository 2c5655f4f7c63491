// The test scene is the quaternion Julia set with c = 0 — exactly the unit ball — so every pixel's
// depth has an analytic answer: the first intersection of its ray with |p| = 1, in double.
//
// Tolerances, from the hit threshold: the march stops where DE(p) = 0.5 |p| ln|p| < eps, and near
// the surface that DE is half the distance, so the stop point lies up to delta = 2 eps (a little
// more, for the curvature of r ln r) outside the sphere. A ray that meets the sphere at incidence
// cosine c crosses the shell 1 < |p| < 1 + delta over sqrt(c^2 + 2 delta + delta^2) - c before
// the exact depth, so it may stop that much nearer; never further (inside the bounding radius 2
// the DE never over-estimates, so the march cannot step through the surface).
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/de_probe.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace fr {
namespace {

struct Analytic {
  bool hit;
  double t;  // exact depth where hit
  double cos_incidence;
  double closest;  // distance from the centre to the ray's closest point
};

Analytic intersect_unit_sphere(glm::dvec3 o, glm::dvec3 d) {
  const double b = glm::dot(o, d), c = glm::dot(o, o) - 1;
  const double disc = b * b - c;
  Analytic a{};
  a.closest = std::sqrt(std::max(glm::dot(o, o) - b * b, 0.0));
  a.hit = disc >= 0;
  if (a.hit) {
    a.t = -b - std::sqrt(disc);
    a.cos_incidence = -glm::dot(glm::normalize(o + a.t * d), d);
  }
  return a;
}

struct BallCase {
  const char* scene;  // the test-only fixture, or the julia plugin with c = 0
  int lanes;
};

class UnitBall : public ::testing::TestWithParam<BallCase> {};

TEST_P(UnitBall, DepthAndMaskMatchTheSphere) {
  const int lanes = GetParam().lanes;
  const bool julia = std::string(GetParam().scene) == "julia";
  auto scene =
      julia ? test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "julia" PLUGIN_SUFFIX)
            : test::unit_ball();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  if (julia) {
    // c = 0 and the slice w = 0: the unit ball (z -> z^2 escapes exactly where |z| > 1). The
    // bounding sphere the update callback sets must contain it, and not be much larger.
    state.params[scene->info.find_param("c")] = fr_value{{0, 0, 0}};
    state.params[scene->info.find_param("c_w")] = fr_value{{0, 0, 0}};
    state.params[scene->info.find_param("slice_w")] = fr_value{{0, 0, 0}};
    std::string error;
    auto instance = SceneInstance::create(scene, &error);
    ASSERT_TRUE(instance->update(state, 0, &error)) << error;
    EXPECT_GE(state.bounding_radius, 1.0);
    EXPECT_LE(state.bounding_radius, 1.1);
  }
  state.camera.eye[0] = 0.4;  // off-axis, so rays cross the surface at all angles
  state.camera.eye[1] = 0.9;
  state.camera.eye[2] = 3.2;
  state.camera.target[1] = 0.1;
  RenderSettings settings;
  settings.width_px = 96;
  settings.height_px = 96;
  settings.lanes = lanes;
  Renderer renderer(test::runtime());
  const FrameImage img = renderer.render(scene->info, state, settings, true);

  const CameraRays rays = make_camera_rays(state.camera, 96, 96);
  int hits = 0, rim = 0, checked = 0;
  double worst_excess = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) {
      const size_t i = static_cast<size_t>(y) * 96 + x;
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      const Analytic a = intersect_unit_sphere(rays.eye, d);
      const double t_ref = a.hit ? a.t : glm::length(rays.eye);
      const double eps = settings.hit_threshold_k * rays.pixel_angle_rad * t_ref;
      const bool rendered_hit = std::isfinite(img.depth[i]);
      ASSERT_TRUE(std::isfinite(img.linear_rgba[4 * i]) &&
                  std::isfinite(img.linear_rgba[4 * i + 1]) &&
                  std::isfinite(img.linear_rgba[4 * i + 2]))
          << "pixel " << x << "," << y;
      // The rim: rays passing within the threshold's shell of the surface may go either way.
      if (std::abs(a.closest - 1) <= 2.5 * eps + 1e-5) {
        ++rim;
        continue;
      }
      ASSERT_EQ(rendered_hit, a.hit) << "pixel " << x << "," << y << " closest " << a.closest;
      if (!a.hit) continue;
      ++hits;
      const double early = a.t - img.depth[i];  // how much nearer than the exact depth
      const double delta = 2.1 * eps;
      const double c = a.cos_incidence;
      const double allowed = std::sqrt(c * c + 2 * delta + delta * delta) - c + 2e-6 * a.t;
      EXPECT_GE(early, -2e-6 * a.t) << "pixel " << x << "," << y << " is behind the surface";
      EXPECT_LE(early, allowed) << "pixel " << x << "," << y << " cos " << c;
      worst_excess = std::max(worst_excess, early / allowed);
      ++checked;
    }
  EXPECT_GT(hits, 96 * 96 / 10) << "the ball should cover a good part of the image";
  EXPECT_LT(rim, hits / 4) << "the rim band (about 2 pixels wide) is a thin ring around the ball";
  RecordProperty("worst_depth_excess_fraction_of_allowed", std::to_string(worst_excess));
  RecordProperty("checked_pixels", checked);
}

INSTANTIATE_TEST_SUITE_P(ScenesAndLanes, UnitBall,
                         ::testing::Values(BallCase{"unit_ball", 1}, BallCase{"unit_ball", 16},
                                           BallCase{"julia", 1}, BallCase{"julia", 16}));

// Lambert shading has an analytic answer on the ball: with one directional light of radiance L
// towards l, no occlusion and no shadow, a hit pixel's linear colour is
// albedo * (ambient + L max(0, n.l)) with n the radial normal at the rendered hit point (which
// lies up to the hit threshold outside the sphere, nearer the rim the more so: at grazing
// incidence that tilts the normal by a few degrees against the exact intersection's). Checked
// per pixel within 1% + 0.002 (the kernel takes the normal by finite differences). Mutations
// caught: the light vector used without normalising it, and a diffuse term 3% too bright.
TEST(UnitBallShading, LambertMatchesTheAnalyticRadiance) {
  auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  fr_light light{};
  light.struct_size = sizeof light;
  light.kind = FR_LIGHT_DIRECTIONAL;
  const glm::dvec3 light_dir(-0.6, -1.0, -1.6);  // the direction the light travels; not unit
  for (int a = 0; a < 3; ++a) light.vector[a] = light_dir[a];
  light.color[0] = 1.0;
  light.color[1] = 0.9;
  light.color[2] = 0.8;
  light.intensity = 1.5;
  state.lights = {light};
  RenderSettings settings;
  settings.width_px = 64;
  settings.height_px = 64;
  settings.shading = ShadingModel::Lambert;
  settings.disabled_stages = FR_FEATURE_AO;
  const FrameImage img = Renderer(test::runtime()).render(scene->info, state, settings, true);

  const CameraRays rays = make_camera_rays(state.camera, 64, 64);
  const glm::dvec3 to_light = -glm::normalize(light_dir);
  int checked = 0, lit = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      const Analytic a = intersect_unit_sphere(rays.eye, d);
      if (!a.hit || std::abs(a.closest - 1) < 0.02) continue;  // misses and the rim
      const size_t i = static_cast<size_t>(y) * 64 + x;
      ASSERT_TRUE(std::isfinite(img.depth[i])) << "pixel " << x << "," << y;
      // The DE 0.5 |p| ln|p| is radial, so its gradient at the rendered hit point (a little
      // outside the sphere, see above) points away from the centre.
      const glm::dvec3 n = glm::normalize(rays.eye + double(img.depth[i]) * d);
      const double cosine = std::max(0.0, glm::dot(n, to_light));
      for (int c = 0; c < 3; ++c) {
        const double expected =
            settings.albedo[c] * (settings.ambient[c] + light.color[c] * light.intensity * cosine);
        EXPECT_NEAR(img.linear_rgba[4 * i + c], expected, 0.01 * expected + 0.002)
            << "pixel " << x << "," << y << " channel " << c << " n.l " << cosine;
      }
      ++checked;
      lit += cosine > 0.1;
    }
  EXPECT_GT(checked, 64 * 64 / 10);
  EXPECT_GT(lit, checked / 4) << "the light should face a good part of the visible ball";
  EXPECT_LT(lit, checked) << "and leave part of it unlit, so the clamp is tested";
}

// The DE itself is 0.5 |p| ln|p| at every point (within float rounding), inside and out.
TEST(UnitBallDe, IsHalfRLogR) {
  auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  std::vector<std::array<float, 3>> pts;
  for (float r : {0.3f, 0.7f, 0.99f, 1.0f, 1.01f, 1.3f, 1.9f})
    for (auto dir : {std::array<float, 3>{1, 0, 0}, {0, 0.6f, 0.8f}, {-0.48f, 0.6f, -0.64f}})
      pts.push_back({r * dir[0], r * dir[1], r * dir[2]});
  const auto de =
      probe_de(test::runtime(), scene->info, make_default_state(scene->info).params, pts);
  for (size_t i = 0; i < pts.size(); ++i) {
    const double r = std::sqrt(double(pts[i][0]) * pts[i][0] + double(pts[i][1]) * pts[i][1] +
                               double(pts[i][2]) * pts[i][2]);
    EXPECT_NEAR(de[i], 0.5 * r * std::log(r), 2e-6 + 1e-5 * std::abs(0.5 * r * std::log(r)))
        << "r = " << r;
  }
}

}  // namespace
}  // namespace fr
