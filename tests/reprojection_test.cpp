// The previous frame carried into a new camera (app/reprojection.hpp), against exact geometry: a
// projection that inverts the camera's rays, and frames of planes at known distances whose
// pixels a sideways move of the camera shifts by a whole number of pixels (parallax: N pixels
// at distance D for a move of N * D * pixel pitch), so where each lands, what is disoccluded and
// which surface wins are known without rendering.
#include "app/reprojection.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace fr {
namespace {

fr_camera camera_at(glm::dvec3 eye, glm::dvec3 target, double fov_deg) {
  fr_camera c{};
  c.struct_size = sizeof c;
  for (int k = 0; k < 3; ++k) {
    c.eye[k] = eye[k];
    c.target[k] = target[k];
  }
  c.up[1] = 1;
  c.fov_deg = fov_deg;
  return c;
}

TEST(Reprojection, ProjectionInvertsTheRays) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 eye(unit(random) * 4 - 2, unit(random) * 4 - 2, unit(random) * 4 - 2);
    const glm::dvec3 target = eye + glm::dvec3(unit(random) - 0.5, unit(random) - 0.5, -1);
    const int w = 2 + static_cast<int>(unit(random) * 300), h = 2 + static_cast<int>(unit(random) * 200);
    const CameraRays rays = make_camera_rays(camera_at(eye, target, 20 + unit(random) * 140), w, h);
    const double x = unit(random) * (w - 1), y = unit(random) * (h - 1);
    const double t = 0.01 + unit(random) * 100;
    const auto at = camera_project(rays, eye + camera_ray_dir(rays, x, y) * t);
    ASSERT_TRUE(at.has_value());
    EXPECT_NEAR(at->x, x, 1e-7 * w);
    EXPECT_NEAR(at->y, y, 1e-7 * h);
    // Behind the eye: nowhere in the image.
    EXPECT_FALSE(camera_project(rays, eye - camera_ray_dir(rays, x, y) * t).has_value());
  }
}

// A frame of the camera looking down -z at planes z = -depth_of(x): each pixel's depth along its
// ray from the plane's distance, its colour a code of its column and row.
struct PlaneFrame {
  std::vector<uint8_t> rgba8;
  std::vector<float> depth;
};

template <class DepthOf>
PlaneFrame plane_frame(const CameraRays& rays, DepthOf plane_distance) {
  PlaneFrame f;
  for (int y = 0; y < rays.height_px; ++y)
    for (int x = 0; x < rays.width_px; ++x) {
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      f.depth.push_back(static_cast<float>(plane_distance(x) / -d.z));
      f.rgba8.insert(f.rgba8.end(), {static_cast<uint8_t>(x), static_cast<uint8_t>(y),
                                     static_cast<uint8_t>(x + 3 * y), 255});
    }
  return f;
}

TEST(Reprojection, ASidewaysMoveShiftsAPlaneByWholePixels) {
  const int w = 64, h = 36, shift_px = 5;
  const double distance = 3;
  const glm::dvec3 eye(0, 0, 0), target(0, 0, -1);
  const CameraRays old_rays = make_camera_rays(camera_at(eye, target, 60), w, h);
  const PlaneFrame old = plane_frame(old_rays, [&](int) { return distance; });
  // At the plane, neighbouring pixel centres are distance * |pixel_step_x| apart.
  const glm::dvec3 move = old_rays.right * (shift_px * distance * glm::length(old_rays.pixel_step_x));
  const CameraRays new_rays = make_camera_rays(camera_at(eye + move, target + move, 60), w, h);
  const ReprojectedFrame r = reproject(old_rays, old.rgba8.data(), old.depth.data(), new_rays);
  ASSERT_EQ(r.reused.size(), size_t(w) * h);
  EXPECT_EQ(r.reused_count, size_t(w - shift_px) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      if (x >= w - shift_px) {  // beyond the old image's right edge: traced fresh
        EXPECT_EQ(r.reused[i], 0) << x << "," << y;
        continue;
      }
      ASSERT_EQ(r.reused[i], 1) << x << "," << y;
      EXPECT_EQ(r.rgba8[i * 4 + 0], x + shift_px) << "the pixel that moved here";
      EXPECT_EQ(r.rgba8[i * 4 + 1], y);
      // The distance along the new ray is what a fresh trace of the plane gives.
      const double fresh = distance / -camera_ray_dir(new_rays, x, y).z;
      EXPECT_NEAR(r.depth[i], fresh, 1e-5 * fresh);
    }
}

TEST(Reprojection, TheNearerSurfaceWinsAndADisocclusionIsTracedFresh) {
  // The left half of the old image sees a plane at distance 2, the right half one at 4: moving
  // the camera right shifts the near one 4 pixels left and the far one 2, so they overlap
  // nowhere, and the 2 columns between them show what neither frame saw.
  const int w = 40, h = 8, near_shift = 4;
  const double near_distance = 2, far_distance = 4;
  const glm::dvec3 eye(0, 0, 0), target(0, 0, -1);
  const CameraRays old_rays = make_camera_rays(camera_at(eye, target, 50), w, h);
  const PlaneFrame old =
      plane_frame(old_rays, [&](int x) { return x < w / 2 ? near_distance : far_distance; });
  const glm::dvec3 move =
      old_rays.right * (near_shift * near_distance * glm::length(old_rays.pixel_step_x));
  const CameraRays new_rays = make_camera_rays(camera_at(eye + move, target + move, 50), w, h);
  const ReprojectedFrame r = reproject(old_rays, old.rgba8.data(), old.depth.data(), new_rays);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      int from = -1;  // the old column expected here, -1: fresh
      if (x < w / 2 - near_shift) from = x + near_shift;
      else if (x >= w / 2 - 2 && x < w - 2) from = x + 2;
      SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
      if (from < 0) {
        EXPECT_EQ(r.reused[i], 0);
      } else {
        ASSERT_EQ(r.reused[i], 1);
        EXPECT_EQ(r.rgba8[i * 4], from);
      }
    }
  // Moving the other way, the near plane slides over the far one: where both land, the near
  // one's colour and distance are kept.
  const CameraRays back_rays =
      make_camera_rays(camera_at(eye - move, target - move, 50), w, h);
  const ReprojectedFrame b = reproject(old_rays, old.rgba8.data(), old.depth.data(), back_rays);
  for (int x = w / 2 + 2; x < w / 2 + near_shift; ++x) {  // near lands on x - 4 + ..., far on x - 2
    const size_t i = size_t(h / 2) * w + x;
    ASSERT_EQ(b.reused[i], 1) << x;
    EXPECT_EQ(b.rgba8[i * 4], x - near_shift) << "the near plane's pixel, column " << x;
  }
}

TEST(Reprojection, SkyIsTracedFresh) {
  const CameraRays rays = make_camera_rays(camera_at({0, 0, 0}, {0, 0, -1}, 60), 16, 9);
  const std::vector<uint8_t> rgba(16 * 9 * 4, 200);
  const std::vector<float> sky(16 * 9, std::numeric_limits<float>::infinity());
  const ReprojectedFrame r = reproject(rays, rgba.data(), sky.data(), rays);
  EXPECT_EQ(r.reused_count, 0u);
}

}  // namespace
}  // namespace fr
