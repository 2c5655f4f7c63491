// The pinhole camera model (render/camera.hpp) against rays computed by hand from its formulas.
#include "render/camera.hpp"
#include "render/frame_constants.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace fr {
namespace {

fr_camera make_camera(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up, double fov_deg) {
  fr_camera c{};
  c.struct_size = sizeof c;
  for (int i = 0; i < 3; ++i) {
    c.eye[i] = eye[i];
    c.target[i] = target[i];
    c.up[i] = up[i];
  }
  c.fov_deg = fov_deg;
  return c;
}

void expect_dir(glm::dvec3 got, glm::dvec3 unnormalised_expected) {
  const glm::dvec3 e = glm::normalize(unnormalised_expected);
  EXPECT_NEAR(got.x, e.x, 1e-12);
  EXPECT_NEAR(got.y, e.y, 1e-12);
  EXPECT_NEAR(got.z, e.z, 1e-12);
}

// Eye (0,0,5) looking at the origin, up +y, fov 90, 3x3: t = (0,0,-5), b = w x t = (-5,0,0),
// v = t x b = (0,25,0); g_x = tan 45 = 1, g_y = 1 * 3/3 = 1; q_x = (-1,0,0), q_y = (0,1,0);
// p_1m = (0,0,-1) - 1*(-1,0,0) - 1*(0,1,0) = (1,-1,-1).
TEST(Camera, SeedVectorsByHand) {
  const CameraRays r = make_camera_rays(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90), 3, 3);
  EXPECT_NEAR(glm::length(r.first_pixel_dir - glm::dvec3(1, -1, -1)), 0, 1e-12);
  EXPECT_NEAR(glm::length(r.pixel_step_x - glm::dvec3(-1, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(glm::length(r.pixel_step_y - glm::dvec3(0, 1, 0)), 0, 1e-12);
  EXPECT_NEAR(r.pixel_angle_rad, std::atan(1.0), 1e-12);
}

TEST(Camera, CornerAndCentreRays) {
  const CameraRays r = make_camera_rays(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90), 3, 3);
  expect_dir(camera_ray_dir(r, 1, 1), {0, 0, -1});    // centre
  expect_dir(camera_ray_dir(r, 0, 0), {-1, 1, -1});   // top-left: left is -x, up is +y
  expect_dir(camera_ray_dir(r, 2, 0), {1, 1, -1});    // top-right
  expect_dir(camera_ray_dir(r, 0, 2), {-1, -1, -1});  // bottom-left
  expect_dir(camera_ray_dir(r, 2, 2), {1, -1, -1});   // bottom-right = p_1m
}

// 4x2 image, fov 60: g_x = tan 30 = 0.5773503, g_y = g_x * 2/4 = 0.2886751;
// q_x = 2 g_x / 3 * (-1,0,0), q_y = 2 g_y / 1 * (0,1,0); p_1m = (g_x, -g_y, -1).
// Pixel (0,0) uses i-1 = 3, j-1 = 1: (g_x - 2 g_x, -g_y + 2 g_y, -1) = (-g_x, g_y, -1).
TEST(Camera, NonSquareImage) {
  const double gx = std::tan(std::numbers::pi / 6), gy = gx * 2 / 4;
  const CameraRays r = make_camera_rays(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60), 4, 2);
  expect_dir(camera_ray_dir(r, 0, 0), {-gx, gy, -1});
  expect_dir(camera_ray_dir(r, 3, 1), {gx, -gy, -1});
  expect_dir(camera_ray_dir(r, 1, 0), {-gx + 2 * gx / 3, gy, -1});
}

// Mandelbulber2's grid (render.pixel_corners), against its own formula: pixel (x, y) of a W x H
// image looks along normalise(u fov, 1, v fov) in (right, forward, up), u = (x / W - 1/2) W / H,
// v = 1/2 - y / H, fov the image plane's height at unit distance; legacy_coordinate_system
// (mirror_vertical) makes v = y / H - 1/2. Fractalis's horizontal field of view for it is
// 2 atan(fov W / (2 H)). W = 4, H = 2, fov 0.8.
TEST(Camera, PixelCornersAreMandelbulber2sGrid) {
  const double fov = 0.8, w = 4, h = 2;
  const double fov_deg = 2 * std::atan(fov * w / (2 * h)) * 180 / std::numbers::pi;
  const fr_camera c = make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, fov_deg);
  const CameraRays r = make_camera_rays(c, 4, 2, false, true);
  const CameraRays m = make_camera_rays(c, 4, 2, true, true);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      const double u = (x / w - 0.5) * w / h, v = 0.5 - y / h, v_legacy = y / h - 0.5;
      // Right is +x, up +y, forward -z here.
      expect_dir(camera_ray_dir(r, x, y), {u * fov, v * fov, -1});
      expect_dir(camera_ray_dir(m, x, y), {u * fov, v_legacy * fov, -1});
    }
  EXPECT_NEAR(r.pixel_angle_rad, std::atan(fov / h), 1e-12);
  // Pixel centres instead (the default): the last column's centre on the right edge.
  const CameraRays centres = make_camera_rays(c, 4, 2);
  expect_dir(camera_ray_dir(centres, 3, 0), {fov, fov / 2, -1});
}

// Looking along +x from (1,2,3) with up +z: forward (1,0,0), left = z x x = (0,1,0), up (0,0,1).
TEST(Camera, RotatedFrame) {
  const CameraRays r = make_camera_rays(make_camera({1, 2, 3}, {4, 2, 3}, {0, 0, 2}, 90), 3, 3);
  EXPECT_EQ(r.eye, glm::dvec3(1, 2, 3));
  expect_dir(camera_ray_dir(r, 1, 1), {1, 0, 0});
  expect_dir(camera_ray_dir(r, 0, 0), {1, 1, 1});    // top-left: left (+y) and up (+z)
  expect_dir(camera_ray_dir(r, 2, 2), {1, -1, -1});  // bottom-right
}

// The up vector need not be perpendicular to the view: only its component across the view
// matters.
TEST(Camera, UpIsOrthogonalised) {
  const CameraRays a = make_camera_rays(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 50), 8, 6);
  const CameraRays b = make_camera_rays(make_camera({0, 0, 5}, {0, 0, 0}, {0, 3, -2}, 50), 8, 6);
  for (double x : {0.0, 3.5, 7.0})
    for (double y : {0.0, 5.0}) {
      EXPECT_NEAR(glm::length(camera_ray_dir(a, x, y) - camera_ray_dir(b, x, y)), 0, 1e-12);
    }
}

TEST(Camera, RejectsDegenerateCameras) {
  EXPECT_TRUE(check_camera(make_camera({1, 1, 1}, {1, 1, 1}, {0, 1, 0}, 45)).has_value());
  EXPECT_TRUE(check_camera(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 0)).has_value());
  EXPECT_TRUE(check_camera(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 180)).has_value());
  EXPECT_TRUE(check_camera(make_camera({0, 0, NAN}, {0, 0, 0}, {0, 1, 0}, 45)).has_value());
  EXPECT_FALSE(check_camera(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45)).has_value());
  EXPECT_EQ(*check_camera(make_camera({1, 1, 1}, {1, 1, 1}, {0, 1, 0}, 45)), "target equals eye");
}

// Up parallel to the view (looking straight down, or up, the default up axis): no refusal, and a
// stable perpendicular, +y, at both poles; the image's right then follows from the model's
// b = w x t by hand: down (t = -z): b = y x -z = -x, right = -b = +x; up (t = +z): right = -x.
// A nearly parallel up (1e-9 off) gives the same picture as exactly parallel, not noise.
TEST(Camera, UpParallelToTheViewTakesAStablePerpendicular) {
  for (const double pole : {+1.0, -1.0}) {
    SCOPED_TRACE(pole);
    const fr_camera c = make_camera({0, 0, 3 * pole}, {0, 0, 0}, {0, 0, 1}, 60);
    EXPECT_FALSE(check_camera(c).has_value());
    const CameraRays r = make_camera_rays(c, 9, 7);
    expect_dir(r.forward, {0, 0, -pole});
    expect_dir(r.up, {0, 1, 0});
    expect_dir(r.right, {pole, 0, 0});
    const CameraRays near =
        make_camera_rays(make_camera({0, 0, 3 * pole}, {0, 0, 0}, {1e-9, 0, 1}, 60), 9, 7);
    for (double x : {0.0, 4.0, 8.0})
      EXPECT_NEAR(glm::length(camera_ray_dir(r, x, 0) - camera_ray_dir(near, x, 0)), 0, 1e-12);
  }
  // Along y, with up y: the stable perpendicular is +z. A zero up takes it too.
  const CameraRays y = make_camera_rays(make_camera({0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 60), 4, 4);
  expect_dir(y.up, {0, 0, 1});
  const CameraRays zero = make_camera_rays(make_camera({0, 5, 0}, {0, 0, 0}, {0, 0, 0}, 60), 4, 4);
  expect_dir(zero.up, {0, 0, 1});
}

TEST(Camera, SinglePixelLooksAtTarget) {
  const CameraRays r = make_camera_rays(make_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45), 1, 1);
  expect_dir(camera_ray_dir(r, 0, 0), {0, 0, -1});
}

// The camera reaches the double kernel as float pairs (hi + lo): their sum must give back the
// double camera to ~1e-15, or a double deep zoom is only float-precise. (GCC 12 once vectorised
// lo into v - v = 0 here; this test failed with that build.)
TEST(FrameConstants, CameraSurvivesAsHiLoPairs) {
  SceneState state;
  state.bounding_radius = 2;
  state.camera.struct_size = sizeof state.camera;
  const glm::dvec3 eye(0.6 * (1 + 1e-9), 0.8 * (1 + 1e-9), 1.0 / 3);
  for (int a = 0; a < 3; ++a) state.camera.eye[a] = eye[a];
  state.camera.up[2] = 1;
  state.camera.fov_deg = 1e-3;
  const CameraRays rays = make_camera_rays(state.camera, 8, 6);
  const fr_frame_constants fc = make_frame_constants(rays, state, RenderSettings{}, 0);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(double(fc.ray_start[a]) + double(fc.ray_start_lo[a]), eye[a], 1e-15)
        << a << ": inside the bounds, rays start at the eye";
    EXPECT_NEAR(double(fc.first_pixel_dir[a]) + double(fc.first_pixel_dir_lo[a]),
                rays.first_pixel_dir[a], 1e-15);
    EXPECT_NEAR(double(fc.pixel_step_x[a]) + double(fc.pixel_step_x_lo[a]), rays.pixel_step_x[a],
                1e-20);
  }
  EXPECT_EQ(fc.start_scale, 0.0f);
}

// A far camera's rays start on a plane just in front of the bounding sphere: the image centre's
// start point lies on the view axis, 1.001 R before the origin's plane, wherever the eye is.
TEST(FrameConstants, FarCameraRaysStartAtTheBounds) {
  for (double distance : {10.0, 1e3, 1e6}) {
    SceneState state;
    state.bounding_radius = 1.5;
    state.camera.struct_size = sizeof state.camera;
    const glm::dvec3 dir = glm::normalize(glm::dvec3(1, 2, 3));
    for (int a = 0; a < 3; ++a) state.camera.eye[a] = dir[a] * distance;
    state.camera.up[1] = 1;
    state.camera.fov_deg = 10;
    const CameraRays rays = make_camera_rays(state.camera, 9, 7);  // odd: a centre pixel
    const fr_frame_constants fc = make_frame_constants(rays, state, RenderSettings{}, 0);
    glm::dvec3 start;
    for (int a = 0; a < 3; ++a) start[a] = double(fc.ray_start[a]) + double(fc.ray_start_lo[a]);
    EXPECT_NEAR(glm::length(start - dir * 1.5 * 1.001), 0, 1e-9 * distance) << distance;
    // The travelled length is the eye's distance to that point.
    const double travelled =
        (double(fc.start_scale) + double(fc.start_scale_lo)) *
        glm::length(rays.first_pixel_dir + rays.pixel_step_x * 4.0 + rays.pixel_step_y * 3.0);
    EXPECT_NEAR(travelled, distance - 1.5 * 1.001, 1e-9 * distance) << distance;
  }
}

}  // namespace
}  // namespace fr
