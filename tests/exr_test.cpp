// OpenEXR output: the passes read back with the OpenEXR library agree with the exact geometry of
// the unit ball (depth along the ray, normal, hit mask), with the albedo the settings give, and
// with the renderer's own linear image bit for bit (32-bit float, lossless ZIP).
#include "cli/cli.hpp"
#include "cli_run.hpp"
#include "exr_read.hpp"
#include "image/exr_write.hpp"
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <glm/geometric.hpp>

#include <sys/stat.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace fr {
namespace {

using test::CliRun;
using test::run;

TEST(Exr, PassesMatchTheUnitBall) {
  auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  state.camera.eye[0] = 0.4;
  state.camera.eye[1] = 0.9;
  state.camera.eye[2] = 3.2;
  RenderSettings settings;
  settings.width_px = 64;
  settings.height_px = 48;
  settings.albedo = {0.25f, 0.5f, 0.75f};
  Renderer renderer(test::runtime());
  const FrameImage img = renderer.render(scene->info, state, settings, true);
  const auto file = test::fresh_dir("exr") / "ball.exr";
  std::string error;
  ASSERT_TRUE(write_exr_atomic(file, img, &error)) << error;

  const test::ExrImage exr = test::read_exr(file);
  ASSERT_EQ(exr.width, 64);
  ASSERT_EQ(exr.height, 48);
  EXPECT_EQ(exr.channel_names,
            (std::set<std::string>{"R", "G", "B", "A", "Z", "N.x", "N.y", "N.z", "albedo.R",
                                   "albedo.G", "albedo.B", "steps", "mask"}));
  const CameraRays rays = make_camera_rays(state.camera, 64, 48);
  int hits = 0, misses = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      const size_t i = size_t(y) * 64 + x;
      auto at = [&](const char* name) { return exr.channels.at(name)[i]; };
      const char* rgba[] = {"R", "G", "B", "A"};
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(at(rgba[c]), img.linear_rgba[4 * i + c]) << rgba[c] << " at " << x << "," << y;
      EXPECT_GE(at("steps"), 1.0f);
      // The exact ray-sphere intersection, in double.
      const glm::dvec3 o = rays.eye, d = camera_ray_dir(rays, x, y);
      const double b = glm::dot(o, d), disc = b * b - (glm::dot(o, o) - 1);
      const double closest = std::sqrt(std::max(glm::dot(o, o) - b * b, 0.0));
      // The march stops within the hit threshold eps of the surface, where the DE (half the
      // distance near the sphere) is below eps: rays that pass within that shell may go either
      // way (render_unit_ball_test.cpp derives the bounds used here).
      const double t_ref = disc >= 0 ? -b - std::sqrt(disc) : glm::length(o);
      const double eps = settings.hit_threshold_k * rays.pixel_angle_rad * t_ref;
      if (std::abs(closest - 1) <= 2.5 * eps + 1e-5) continue;
      if (disc < 0) {
        ++misses;
        EXPECT_EQ(at("mask"), 0.0f) << x << "," << y;
        EXPECT_TRUE(std::isinf(at("Z")) && at("Z") > 0) << x << "," << y;
        for (const char* c : {"N.x", "N.y", "N.z", "albedo.R", "albedo.G", "albedo.B"})
          EXPECT_EQ(at(c), 0.0f) << c << " at " << x << "," << y;
        continue;
      }
      ++hits;
      const double t = t_ref;
      const glm::dvec3 n = glm::normalize(o + t * d);
      EXPECT_EQ(at("mask"), 1.0f) << x << "," << y;
      // A little nearer than the sphere (the shell 1 < |p| < 1 + 2.1 eps), never further.
      const double c = -glm::dot(n, d), delta = 2.1 * eps;
      const double early = std::sqrt(c * c + 2 * delta + delta * delta) - c + 2e-6 * t;
      EXPECT_LE(at("Z"), t + 2e-6 * t) << x << "," << y;
      EXPECT_GE(at("Z"), t - early) << x << "," << y;
      const glm::dvec3 rendered_n(at("N.x"), at("N.y"), at("N.z"));
      // The DE's gradient at the point the march stopped is radial: the normal there.
      const glm::dvec3 radial = glm::normalize(o + double(at("Z")) * d);
      EXPECT_GT(glm::dot(rendered_n, radial), 0.9995) << x << "," << y;
      EXPECT_NEAR(glm::length(rendered_n), 1.0, 1e-4);
      EXPECT_FLOAT_EQ(at("albedo.R"), 0.25f);
      EXPECT_FLOAT_EQ(at("albedo.G"), 0.5f);
      EXPECT_FLOAT_EQ(at("albedo.B"), 0.75f);
    }
  EXPECT_GT(hits, 300);
  EXPECT_GT(misses, 300);
}

// `render --out FILE.exr` writes the passes; what cannot be an EXR is refused before rendering.
TEST(Exr, RenderWritesExrAndRefusesWhatCannotBeOne) {
  const auto dir = test::fresh_dir("exr_cli");
  const auto file = dir / "sponge.EXR";
  CliRun r = run({"render", "--scene", "menger", "--size", "40x30", "--out", file.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const test::ExrImage exr = test::read_exr(file);
  EXPECT_EQ(exr.width, 40);
  EXPECT_EQ(exr.channel_names.size(), 13u);
  float masked = 0;
  for (float m : exr.channels.at("mask")) masked += m;
  EXPECT_GT(masked, 0.0f);
  EXPECT_LT(masked, 40.0f * 30);

  r = run({"render", "--size", "65536x100", "--out", (dir / "big.exr").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--size width: 65536 is outside [1, 65535]"), std::string::npos) << r.err;
  const auto fifo = dir / "pipe.exr";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  r = run({"render", "--size", "40x30", "--out", fifo.string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("an EXR file cannot go to a pipe or device"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "big.exr"));
}

}  // namespace
}  // namespace fr
