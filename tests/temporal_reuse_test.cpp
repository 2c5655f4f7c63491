// Temporal reuse (app/temporal_reuse.hpp) against answers known without it: a lattice render is
// the whole image's render at those pixels; a camera that does not move, or moves sideways over
// planes by whole pixels (parallax: N pixels at distance D for a move of N * D * pixel pitch),
// carries every pixel to where exact geometry says; what was hidden or outside is not carried;
// a half turn carries nothing; and in the explorer, a frame whose parameters changed carries
// nothing of the frames before it.
#include "app/temporal_reuse.hpp"
#include "app/explorer.hpp"
#include "render/renderer.hpp"
#include "test_paths.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

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

TEST(LatticePhase, EveryPixelOncePerCycle) {
  for (const auto& [sx, sy] : std::vector<std::pair<int, int>>{{2, 2}, {3, 2}, {3, 3}, {5, 4}}) {
    std::vector<int> seen(static_cast<size_t>(sx * sy), 0);
    for (uint64_t frame = 7; frame < 7 + static_cast<uint64_t>(sx * sy); ++frame) {
      const LatticePhase p = lattice_phase(sx, sy, frame);
      ASSERT_LT(p.x0, sx);
      ASSERT_LT(p.y0, sy);
      ++seen[static_cast<size_t>(p.y0 * sx + p.x0)];
    }
    for (int n : seen) EXPECT_EQ(n, 1) << sx << "x" << sy;
  }
}

// The renderer traces a lattice as the whole image's pixels: the same colour and depth (the same
// rays, but the lattice's cone pre-pass has blocks of its own, so a march may start elsewhere and
// end a float rounding apart).
TEST(LatticeRender, EqualsTheWholeRenderAtItsPixels) {
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  state.camera = camera_at({0.4, 0.3, 3}, {0, 0, 0}, 50);
  RenderSettings s;
  s.width_px = 67;
  s.height_px = 41;
  renderer.render_sample(scene->info, state, s, 0, Readback::Everything);
  FrameImage full;
  renderer.finish(s, Readback::Everything, full);
  const LatticePhase phase{3, 2, 2, 1};
  RenderSettings l = s;
  l.window =
      ImageWindow{s.width_px, s.height_px, phase.x0, phase.y0, phase.stride_x, phase.stride_y};
  l.width_px = phase.width_px(s.width_px);
  l.height_px = phase.height_px(s.height_px);
  renderer.render_sample(scene->info, state, l, 0, Readback::Everything);
  FrameImage lattice;
  renderer.finish(l, Readback::Everything, lattice);
  int hits = 0;
  for (int j = 0; j < l.height_px; ++j)
    for (int i = 0; i < l.width_px; ++i) {
      const size_t a = static_cast<size_t>(j) * l.width_px + i;
      const size_t b = static_cast<size_t>(phase.y0 + j * phase.stride_y) * s.width_px +
                       static_cast<size_t>(phase.x0 + i * phase.stride_x);
      SCOPED_TRACE(std::to_string(i) + "," + std::to_string(j));
      if (std::isfinite(full.depth[b])) {
        ++hits;
        ASSERT_NEAR(lattice.depth[a], full.depth[b], 1e-4 * full.depth[b]);
      } else {
        ASSERT_FALSE(std::isfinite(lattice.depth[a]));
      }
      for (int c = 0; c < 4; ++c) ASSERT_NEAR(lattice.rgba8[4 * a + c], full.rgba8[4 * b + c], 2);
    }
  EXPECT_GT(hits, l.width_px * l.height_px / 8) << "the ball is in view";
}

// A frame of planes z = -distance(x) seen by a camera looking down -z: each pixel's depth along
// its ray, its colour a code of its column and row.
struct PlaneFrame {
  std::vector<uint8_t> rgba8;
  std::vector<float> depth;
};

template <class Distance>
PlaneFrame plane_frame(const CameraRays& rays, Distance plane_distance) {
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

// The lattice `phase` of a whole frame.
PlaneFrame lattice_of(const PlaneFrame& whole, int width_px, int height_px,
                      const LatticePhase& phase) {
  PlaneFrame l;
  for (int j = 0; j < phase.height_px(height_px); ++j)
    for (int i = 0; i < phase.width_px(width_px); ++i) {
      const size_t at = static_cast<size_t>(phase.y0 + j * phase.stride_y) * width_px +
                        static_cast<size_t>(phase.x0 + i * phase.stride_x);
      l.depth.push_back(whole.depth[at]);
      l.rgba8.insert(l.rgba8.end(), whole.rgba8.begin() + 4 * at, whole.rgba8.begin() + 4 * at + 4);
    }
  return l;
}

TEST(TemporalReuse, AStillCameraCarriesEveryPixelExactly) {
  const int w = 48, h = 30;
  const CameraRays rays = make_camera_rays(camera_at({0, 0, 0}, {0, 0, -1}, 60), w, h);
  const PlaneFrame frame = plane_frame(rays, [](int x) { return 2.0 + 0.05 * x; });
  TemporalReuse reuse;
  reuse.compose(rays, LatticePhase{}, frame.rgba8.data(), frame.depth.data());
  const LatticePhase phase{3, 3, 1, 2};
  const PlaneFrame l = lattice_of(frame, w, h, phase);
  const uint8_t* shown = reuse.compose(rays, phase, l.rgba8.data(), l.depth.data());
  EXPECT_EQ(reuse.counts().fresh, l.depth.size());
  EXPECT_EQ(reuse.counts().reused, size_t(w) * h - l.depth.size());
  EXPECT_EQ(reuse.counts().filled, 0u);
  for (size_t i = 0; i < frame.rgba8.size(); ++i) ASSERT_EQ(shown[i], frame.rgba8[i]) << i / 4;
}

TEST(TemporalReuse, ASidewaysMoveCarriesAPlaneByWholePixels) {
  const int w = 64, h = 36, shift_px = 5;
  const double distance = 3;
  const glm::dvec3 eye(0, 0, 0), target(0, 0, -1);
  const CameraRays old_rays = make_camera_rays(camera_at(eye, target, 60), w, h);
  const PlaneFrame old = plane_frame(old_rays, [&](int) { return distance; });
  const glm::dvec3 move =
      old_rays.right * (shift_px * distance * glm::length(old_rays.pixel_step_x));
  const CameraRays new_rays = make_camera_rays(camera_at(eye + move, target + move, 60), w, h);
  // The new camera's fresh lattice: the plane again, coloured by where each pixel was before.
  PlaneFrame fresh = plane_frame(new_rays, [&](int) { return distance; });
  for (size_t i = 0; i < fresh.rgba8.size(); i += 4) fresh.rgba8[i] += shift_px;
  TemporalReuse reuse;
  reuse.compose(old_rays, LatticePhase{}, old.rgba8.data(), old.depth.data());
  const LatticePhase phase{2, 2, 0, 0};
  const PlaneFrame l = lattice_of(fresh, w, h, phase);
  const uint8_t* shown = reuse.compose(new_rays, phase, l.rgba8.data(), l.depth.data());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w - shift_px; ++x) {
      const size_t i = size_t(y) * w + x;
      ASSERT_EQ(shown[4 * i], x + shift_px) << x << "," << y << ": the pixel that moved here";
      ASSERT_EQ(shown[4 * i + 1], y) << x << "," << y;
    }
  // Beyond the old image's right edge nothing was carried: only the lattice's own pixels there.
  size_t edge_fresh = 0;
  for (int x = w - shift_px; x < w; ++x) edge_fresh += x % 2 == 0 ? h / 2 : 0;
  EXPECT_EQ(reuse.counts().filled, size_t(shift_px) * h - edge_fresh);
  EXPECT_EQ(reuse.counts().reused + reuse.counts().fresh + reuse.counts().filled, size_t(w) * h);
}

TEST(TemporalReuse, MovingTowardsAPlaneEachPixelTakesTheSampleThatLandsNearest) {
  // A plane facing the camera, 1.2 away, then 1.0 away: the picture grows 1.2 times about its
  // centre c, so the old pixel q lands at c + 1.2 (q - c) (similar triangles, not the projection
  // the code does). Samples land 1.2 px apart: a pixel has no sample of its own within half a
  // pixel in places, but always one within 0.6 px in x and in y (0.85 px < 0.87 px): none is
  // filled, and each takes the nearest, per axis the old pixel round((p - c) / 1.2 + c) (never
  // within 0.1 px of a tie at these sizes: the centre is a half-integer).
  const int w = 64, h = 36;
  const double m = 1.2, fov_deg = 20;  // narrow: the plane's distances from the new eye within 5%
  const CameraRays old_rays = make_camera_rays(camera_at({0, 0, 0}, {0, 0, -1}, fov_deg), w, h);
  const CameraRays new_rays =
      make_camera_rays(camera_at({0, 0, -0.2}, {0, 0, -1.2}, fov_deg), w, h);
  const PlaneFrame old = plane_frame(old_rays, [&](int) { return m; });
  PlaneFrame fresh = plane_frame(new_rays, [](int) { return 1.0; });
  for (size_t i = 0; i < fresh.rgba8.size(); i += 4) fresh.rgba8[i + 3] = 7;  // told apart
  TemporalReuse reuse;
  reuse.compose(old_rays, LatticePhase{}, old.rgba8.data(), old.depth.data());
  const LatticePhase phase{2, 2, 0, 0};
  const PlaneFrame l = lattice_of(fresh, w, h, phase);
  const uint8_t* shown = reuse.compose(new_rays, phase, l.rgba8.data(), l.depth.data());
  EXPECT_EQ(reuse.counts().filled, 0u);
  EXPECT_EQ(reuse.counts().rejected, 0u);
  const auto nearest_old = [&](int p, int size) {
    const double c = 0.5 * (size - 1);
    return static_cast<int>(std::lround((p - c) / m + c));
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x % 2 == 0 && y % 2 == 0) continue;  // the fresh lattice's own
      const size_t i = size_t(y) * w + x;
      const int qx = nearest_old(x, w), qy = nearest_old(y, h);
      ASSERT_EQ(shown[4 * i + 3], 255) << x << "," << y << ": carried, not the fresh lattice's";
      ASSERT_EQ(shown[4 * i], qx) << x << "," << y;
      ASSERT_EQ(shown[4 * i + 1], qy) << x << "," << y;
    }
}

TEST(TemporalReuse, WhatWasHiddenIsNotCarried) {
  // The left half of the old image sees a plane at distance 2, the right half one at 4: moving
  // right shifts the near one 4 pixels left and the far one 2, so the 2 columns between them
  // show what the old frame did not see, and must not be carried.
  const int w = 40, h = 12, near_shift = 4;
  const double near_distance = 2, far_distance = 4;
  const glm::dvec3 eye(0, 0, 0), target(0, 0, -1);
  const CameraRays old_rays = make_camera_rays(camera_at(eye, target, 50), w, h);
  const auto planes = [&](int x) { return x < w / 2 ? near_distance : far_distance; };
  const PlaneFrame old = plane_frame(old_rays, planes);
  const glm::dvec3 move =
      old_rays.right * (near_shift * near_distance * glm::length(old_rays.pixel_step_x));
  const CameraRays new_rays = make_camera_rays(camera_at(eye + move, target + move, 50), w, h);
  // The fresh lattice: the near plane's old columns, then the far plane, seen before only where
  // it is not uncovered (colour 200 there).
  PlaneFrame fresh = plane_frame(
      new_rays, [&](int x) { return x < w / 2 - near_shift ? near_distance : far_distance; });
  for (int x = 0; x < w; ++x)
    for (int y = 0; y < h; ++y)
      fresh.rgba8[4 * (size_t(y) * w + x)] =
          static_cast<uint8_t>(x < w / 2 - near_shift ? x + near_shift
                               : x < w / 2 - 2        ? 200
                                                      : x + 2);
  TemporalReuse reuse;
  reuse.compose(old_rays, LatticePhase{}, old.rgba8.data(), old.depth.data());
  const LatticePhase phase{2, 2, 1, 1};
  const PlaneFrame l = lattice_of(fresh, w, h, phase);
  const uint8_t* shown = reuse.compose(new_rays, phase, l.rgba8.data(), l.depth.data());
  for (int y = 1; y < h - 1; ++y) {
    // Uncovered: the fresh lattice's (200 there, mixed with its near-plane neighbour where it
    // interpolates), never a carried colour (the old frame's are column numbers, below 40).
    for (int x = w / 2 - near_shift; x < w / 2 - 2; ++x)
      EXPECT_GE(shown[4 * (size_t(y) * w + x)], 100) << "uncovered, " << x << "," << y;
    for (int x = 0; x < w / 2 - near_shift - 1; ++x)
      EXPECT_EQ(shown[4 * (size_t(y) * w + x)], x + near_shift) << "near plane, " << x;
    for (int x = w / 2 - 1; x < w - 3; ++x)
      EXPECT_EQ(shown[4 * (size_t(y) * w + x)], x + 2) << "far plane, " << x;
  }
}

TEST(TemporalReuse, AHalfTurnCarriesNothing) {
  const int w = 32, h = 18;
  const CameraRays ahead = make_camera_rays(camera_at({0, 0, 0}, {0, 0, -1}, 60), w, h);
  const CameraRays behind = make_camera_rays(camera_at({0, 0, 0}, {0, 0, 1}, 60), w, h);
  const PlaneFrame old = plane_frame(ahead, [](int) { return 3.0; });
  std::vector<float> sky(size_t(w) * h, std::numeric_limits<float>::infinity());
  std::vector<uint8_t> blue(size_t(w) * h * 4, 0);
  for (size_t i = 2; i < blue.size(); i += 4) blue[i] = 255;
  TemporalReuse reuse;
  reuse.compose(ahead, LatticePhase{}, old.rgba8.data(), old.depth.data());
  const LatticePhase phase{3, 3, 0, 0};
  const uint8_t* shown = reuse.compose(behind, phase, blue.data(), sky.data());
  EXPECT_EQ(reuse.counts().reused, 0u);
  for (size_t i = 0; i < size_t(w) * h; ++i) ASSERT_EQ(shown[4 * i + 2], 255) << i;
}

// In the explorer: frames while only the camera moves reuse; the frame after a parameter
// changed is scaled and carries nothing (its pixels would be stale), the one after that reuses
// again; explorer.temporal = false never reuses.
TEST(TemporalReuseInTheExplorer, AChangedParameterReusesNothing) {
  for (const bool temporal : {true, false}) {
    SCOPED_TRACE(temporal ? "temporal" : "scaled");
    const auto dir = test::folder_of_one_scene("temporal_plugins", SCENE_PLUGIN_DIR, "mandelbulb");
    std::vector<SceneEvent> events;
    SceneLibrary library({dir}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
    ASSERT_EQ(library.slots().size(), 1u);
    Settings settings;
    settings.explorer.temporal = temporal;
    Explorer explorer(settings, test::worker(), library, "mandelbulb");
    InputState fly;
    fly.held.insert(Action::MoveForward);
    double now = 0;
    const auto frame = [&](const InputState& in) {
      explorer.update(in, 1.0 / 30, now += 1.0 / 30);
      return explorer.render(96, 54);
    };
    // The first frame is scaled (a new scene), the second a lattice with nothing to carry yet.
    for (int i = 0; i < 3; ++i) ASSERT_NE(frame(fly), nullptr);
    EXPECT_EQ(explorer.stats().temporal, temporal);
    if (temporal) {
      EXPECT_GT(explorer.stats().reuse.reused, 0u);
    }
    explorer.current().state.params[0].v[0] += 0.5f;  // what the overlay's slider does
    explorer.mark_changed();
    ASSERT_NE(frame(fly), nullptr);
    EXPECT_FALSE(explorer.stats().temporal) << "a changed parameter: nothing carried";
    EXPECT_EQ(explorer.stats().reuse.reused, 0u);
    ASSERT_NE(frame(fly), nullptr);
    EXPECT_EQ(explorer.stats().temporal, temporal) << "only the camera moved: reuse again";
  }
}

// A scene whose update callback moves a parameter every frame (the Julia set's c on its circle,
// FR-2.4): no frame reuses anything, however the camera moves.
TEST(TemporalReuseInTheExplorer, AnAnimatedParameterNeverReuses) {
  const auto dir = test::folder_of_one_scene("temporal_animated", SCENE_PLUGIN_DIR, "julia");
  std::vector<SceneEvent> events;
  SceneLibrary library({dir}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
  ASSERT_EQ(library.slots().size(), 1u);
  Settings settings;
  settings.explorer.temporal = true;
  Explorer explorer(settings, test::worker(), library, "julia");
  SceneSlot& slot = explorer.current();
  const auto& params = slot.scene->info.params;
  const auto animate = std::find_if(params.begin(), params.end(),
                                    [](const ParamInfo& p) { return p.key == "animate_c"; });
  ASSERT_NE(animate, params.end());
  slot.state.params[static_cast<size_t>(animate - params.begin())].v[0] = 1;
  explorer.mark_changed();
  InputState fly;
  fly.held.insert(Action::MoveForward);
  for (int i = 1; i <= 6; ++i) {
    explorer.update(fly, 1.0 / 30, i / 30.0);
    ASSERT_NE(explorer.render(96, 54), nullptr);
    EXPECT_FALSE(explorer.stats().temporal) << "frame " << i;
    EXPECT_EQ(explorer.stats().reuse.reused, 0u) << "frame " << i;
  }
}

}  // namespace
}  // namespace fr
