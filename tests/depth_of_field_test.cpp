// The thin lens (kernels/lens.cl) against geometry computed here in double (issue 36's lens test):
// the unit ball out of focus, lit by ambient light alone against a black sky, so that a pixel's
// accumulated value is the share of its samples that hit the ball. Each sample is a ray from a
// point of the aperture disc through the pixel's point on the focus plane; the share that meets
// the sphere, over the disc and the pixel's jitter, is the coverage the image must show. A lens
// whose blur were 20% larger or smaller than the thin-lens formula's would miss it.
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/kernel_assembly.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace fr {
namespace {

// Whether the point (a, b) of the aperture's plane, in units of its radius, is in the aperture:
// the unit disc, or (blades >= 3) the regular polygon inscribed in it with a vertex at angle
// `first_vertex_rad` (lens.cl puts it at the top, pi / 2).
bool in_aperture(double a, double b, int blades, double first_vertex_rad) {
  if (blades < 3) return a * a + b * b <= 1;
  // Inside every edge: the edge between vertices j and j + 1 is at distance cos(pi / n) from the
  // centre, along the direction halfway between them.
  const double half = std::numbers::pi / blades;
  for (int j = 0; j < blades; ++j) {
    const double mid = first_vertex_rad + (2 * j + 1) * half;
    if (a * std::cos(mid) + b * std::sin(mid) > std::cos(half)) return false;
  }
  return true;
}

// The share of thin-lens rays of pixel (x, y) that meet the unit sphere at the origin: points of
// the aperture (a grid over its bounding square, those inside it) and the pixel's square, both
// on regular grids. A ray counts as the march counts it: where the DE comes below its hit
// threshold, k t times the pixel angle. The fixture's DE, 0.5 |p| ln |p|, is half the distance
// near the surface: within 2 k t times the pixel angle of it.
double thin_lens_coverage(const CameraRays& rays, double x, double y, double radius,
                          double focus_distance, double threshold_k, int blades = 0,
                          double first_vertex_rad = std::numbers::pi / 2) {
  constexpr int kGrid = 32, kJitter = 3;
  int hits = 0, total = 0;
  for (int jy = 0; jy < kJitter; ++jy)
    for (int jx = 0; jx < kJitter; ++jx) {
      const glm::dvec3 d =
          camera_ray_dir(rays, x + (jx + 0.5) / kJitter - 0.5, y + (jy + 0.5) / kJitter - 0.5);
      const glm::dvec3 focus = rays.eye + d * (focus_distance / glm::dot(d, rays.forward));
      for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
          const double a = 2 * (i + 0.5) / kGrid - 1, b = 2 * (j + 0.5) / kGrid - 1;
          if (!in_aperture(a, b, blades, first_vertex_rad)) continue;
          const glm::dvec3 origin = rays.eye + rays.right * (radius * a) + rays.up * (radius * b);
          const glm::dvec3 dir = glm::normalize(focus - origin);
          // The ray's closest approach to the centre, at t = -b.
          const double along = glm::dot(origin, dir);
          const double closest2 = glm::dot(origin, origin) - along * along;
          const double reach = 1 + 2 * threshold_k * -along * rays.pixel_angle_rad;
          hits += -along > 0 && closest2 < reach * reach;
          ++total;
        }
    }
  return static_cast<double>(hits) / total;
}

// The unit ball seen from (0, 0, eye_z) along -z, with one light of no intensity (without any,
// the renderer adds its own).
SceneState ball_view(const SceneInfo& info, double eye_z, double fov_deg) {
  SceneState state = make_default_state(info);
  state.camera = fr_camera{};
  state.camera.struct_size = sizeof(fr_camera);
  state.camera.eye[2] = eye_z;
  state.camera.up[1] = 1;
  state.camera.fov_deg = fov_deg;
  fr_light dark{};
  dark.struct_size = sizeof dark;
  dark.kind = FR_LIGHT_DIRECTIONAL;
  dark.vector[1] = 1;
  state.lights = {dark};
  return state;
}

TEST(DepthOfField, ABlurredSilhouetteIsTheThinLensDisc) {
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const SceneState state = ball_view(scene->info, 4, 50);
  RenderSettings s;
  s.width_px = s.height_px = 48;
  s.samples = 256;
  s.aperture_radius = 0.55f;  // the silhouette (3.75 away) blurs over ~4 pixels each side
  s.focus_distance = 2.5f;
  s.disabled_stages = all_optional_stages() & ~kStageDepthOfField;
  s.sky_zenith = s.sky_horizon = {0, 0, 0};
  s.ambient = {1, 1, 1};
  s.albedo = {0.5f, 0.5f, 0.5f};
  s.hit_threshold_k = 0.05f;  // silhouettes grown by a tenth of a pixel, not half
  Renderer renderer(test::runtime());
  const FrameImage image = renderer.render(scene->info, state, s, /*read_linear=*/true);
  ASSERT_EQ(image.linear_rgba.size(), size_t(48) * 48 * 4);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  double error = 0, error_small = 0, error_large = 0;
  int blurred = 0, expected_blurred = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      const double shown = image.linear_rgba[4 * (size_t(y) * s.width_px + x)] / 0.5;
      const auto coverage = [&](double aperture) {
        return thin_lens_coverage(rays, x, y, aperture, s.focus_distance, s.hit_threshold_k);
      };
      const double expected = coverage(s.aperture_radius);
      error += std::abs(shown - expected);
      error_small += std::abs(shown - coverage(0.8 * s.aperture_radius));
      error_large += std::abs(shown - coverage(1.2 * s.aperture_radius));
      blurred += shown > 0.05 && shown < 0.95;
      expected_blurred += expected > 0.05 && expected < 0.95;
      // 256 samples: a share's standard deviation is at most 0.031.
      EXPECT_NEAR(shown, expected, 0.15) << x << "," << y;
    }
  const double n = s.width_px * s.height_px;
  error /= n;
  EXPECT_LT(error, 0.01) << "mean coverage error";
  EXPECT_GT(expected_blurred, 300) << "the silhouette really is blurred";
  EXPECT_NEAR(blurred, expected_blurred, 0.1 * expected_blurred);
  // The measure tells a 20% wrong blur apart.
  EXPECT_GT(error_small / n, 2 * error);
  EXPECT_GT(error_large / n, 2 * error);
}

// Issue 36's lens test under the path integrator, with a three-bladed aperture: the ball glows
// (emission x colour 0.5) under a black sky with no light, so a pixel shows 0.5 x the share of
// its samples that hit it. Far behind the focus, with a wide aperture, the ball's image is
// mostly the aperture's shape (bokeh). The triangle's coverage must fit, and must fit better
// than the disc's of the same radius or the triangle turned upside down.
TEST(DepthOfField, APathTracedBladedApertureBlursIntoItsPolygon) {
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const SceneState state = ball_view(scene->info, 8, 30);
  RenderSettings s;
  s.integrator = Integrator::Path;
  s.width_px = s.height_px = 48;
  s.samples = 1024;
  s.aperture_radius = 1;  // the ball (7 degrees across) blurs by 12 degrees
  s.aperture_blades = 3;
  s.focus_distance = 3;
  s.disabled_stages = all_optional_stages() & ~kStageDepthOfField;
  s.sky_zenith = s.sky_horizon = {0, 0, 0};
  s.albedo = {0.5f, 0.5f, 0.5f};
  s.emission = 1;
  s.hit_threshold_k = 0.05f;
  Renderer renderer(test::runtime());
  const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  double error = 0, error_disc = 0, error_turned = 0;
  int blurred = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      const double shown = image.linear_rgba[4 * (size_t(y) * s.width_px + x)] / 0.5;
      const auto coverage = [&](int blades, double first_vertex_rad) {
        return thin_lens_coverage(rays, x, y, s.aperture_radius, s.focus_distance,
                                  s.hit_threshold_k, blades, first_vertex_rad);
      };
      const double expected = coverage(3, std::numbers::pi / 2);
      error += std::abs(shown - expected);
      error_disc += std::abs(shown - coverage(0, 0));
      error_turned += std::abs(shown - coverage(3, -std::numbers::pi / 2));
      blurred += expected > 0.05 && expected < 0.95;
      EXPECT_NEAR(shown, expected, 0.15) << x << "," << y;
    }
  const double n = s.width_px * s.height_px;
  EXPECT_LT(error / n, 0.01) << "mean coverage error";
  EXPECT_GT(blurred, 300) << "the silhouette really is blurred";
  EXPECT_GT(error_disc, 2 * error) << "the disc's blur is told apart";
  EXPECT_GT(error_turned, 2 * error) << "the upside-down triangle's blur is told apart";
}

}  // namespace
}  // namespace fr
