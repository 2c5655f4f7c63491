// The sky as an HDR panorama (render.environment): the reader against files written here byte by
// byte (Radiance RGBE values chosen to be exact) and by the EXR writer, and every way a file can
// be wrong; then renders against answers computed here in double from the panorama itself:
//  - where rays leave the scene, both integrators show the panorama's bilinear value in the
//    exact direction of the pixel (its zenith the camera's up vector, turned by the rotation);
//  - a diffuse ball of albedo 1 under a uniform panorama shows the panorama (white furnace:
//    next-event estimation of the panorama and bounces that find it, weighted by multiple
//    importance sampling, add up to the light once, not twice or half);
//  - a ball under a dim sky with a small sun in it shows, at each pixel, the irradiance that
//    integrating the panorama over the hemisphere in double gives, at modest sample counts (the
//    sun is found by sampling the panorama in proportion to its light, in the right place).
#include "image/exr_write.hpp"
#include "io/environment_image.hpp"
#include "path_test_support.hpp"
#include "render/kernel_assembly.hpp"
#include "render/renderer.hpp"
#include "scene/camera_up.hpp"
#include "settings/settings.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <vector>

namespace fr {
namespace {

using Rgb = std::array<float, 3>;
using Panorama = std::function<Rgb(int x, int y)>;

// A pixel as Radiance's shared-exponent RGBE: value = byte * 2^(exponent - 136).
std::array<uint8_t, 4> rgbe(const Rgb& v) {
  const float m = std::max(v[0], std::max(v[1], v[2]));
  if (m < 1e-32f) return {0, 0, 0, 0};
  int e = 0;
  const double mantissa = std::frexp(m, &e);
  const double scale = mantissa * 256.0 / m;
  return {static_cast<uint8_t>(v[0] * scale), static_cast<uint8_t>(v[1] * scale),
          static_cast<uint8_t>(v[2] * scale), static_cast<uint8_t>(e + 128)};
}

// A flat (not run-length encoded) Radiance file: the header, then the pixels row by row.
std::string hdr_bytes(int w, int h, const Panorama& f) {
  std::string out = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " +
                    std::to_string(w) + "\n";
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (uint8_t b : rgbe(f(x, y))) out += static_cast<char>(b);
  return out;
}

std::filesystem::path write_file(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

std::filesystem::path write_hdr(const std::filesystem::path& file, int w, int h,
                                const Panorama& f) {
  return write_file(file, hdr_bytes(w, h, f));
}

TEST(EnvironmentImage, ReadsARadianceFileExactly) {
  const auto dir = test::fresh_dir("environment_read");
  // Eighths are exact in RGBE: (x + 1) / 8, (y + 1) / 8, 1 / 8.
  const auto file = write_hdr(dir / "ramp.hdr", 16, 8, [](int x, int y) {
    return Rgb{(x + 1) / 8.0f, (y + 1) / 8.0f, 1 / 8.0f};
  });
  EnvironmentImage image;
  std::string error;
  ASSERT_TRUE(read_environment_image(file, &image, &error)) << error;
  ASSERT_EQ(image.width_px, 16);
  ASSERT_EQ(image.height_px, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      const float* p = &image.rgb[3 * (y * 16 + x)];
      ASSERT_EQ(p[0], (x + 1) / 8.0f) << x << "," << y;
      ASSERT_EQ(p[1], (y + 1) / 8.0f) << x << "," << y;
      ASSERT_EQ(p[2], 1 / 8.0f) << x << "," << y;
    }
}

TEST(EnvironmentImage, RefusesEveryBadFileSayingWhatIsWrong) {
  const auto dir = test::fresh_dir("environment_bad");
  const Panorama grey = [](int, int) { return Rgb{0.5f, 0.5f, 0.5f}; };
  const std::string good = hdr_bytes(16, 8, grey);
  struct Case {
    std::filesystem::path file;
    const char* says;
  };
  const Case cases[] = {
      {dir / "missing.hdr", "no such file"},
      {dir, "not a file"},
      // A whole row and a bit short: stb_image alone would fill it with black and succeed.
      {write_file(dir / "truncated.hdr", good.substr(0, good.size() - 70)), "truncated"},
      {write_file(dir / "one_byte_short.hdr", good.substr(0, good.size() - 1)), "truncated"},
      {write_file(dir / "text.hdr", "this is not an image\n"), "not a Radiance HDR"},
      {write_file(dir / "empty.exr", ""), "not a Radiance HDR"},
      {write_file(dir / "bad_header.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X\n"),
       "not a readable Radiance HDR"},
      // A header asking for 800 MB of pixels, with none behind it: refused before reading them.
      {write_file(dir / "huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 10000 +X 20000\n"),
       "largest panorama"},
      {write_hdr(dir / "photo.hdr", 24, 8, grey), "twice as wide as it is high"},
      {write_file(dir / "not_exr.exr", std::string("\x76\x2f\x31\x01", 4) + "garbage"), "OpenEXR"},
  };
  for (const Case& c : cases) {
    EnvironmentImage image;
    std::string error;
    EXPECT_FALSE(read_environment_image(c.file, &image, &error)) << c.file;
    EXPECT_NE(error.find(c.says), std::string::npos) << c.file << ": " << error;
    EXPECT_NE(error.find(c.file.filename().string()), std::string::npos) << error;
    EXPECT_TRUE(image.rgb.empty());
  }
  // The whole file reads.
  EnvironmentImage image;
  std::string error;
  EXPECT_TRUE(read_environment_image(write_file(dir / "good.hdr", good), &image, &error)) << error;
}

TEST(EnvironmentImage, ReadsOpenExrInFloatAndRefusesANaN) {
  if (!exr_unavailable_reason().empty()) GTEST_SKIP() << exr_unavailable_reason();
  const auto dir = test::fresh_dir("environment_exr");
  FrameImage frame;
  const FramePassPointers passes = size_frame_image(frame, 8, 4, Readback::Everything);
  for (int i = 0; i < 32; ++i) {
    // 1e5 is beyond half's range (65504): read as half, it would be infinite.
    passes.linear_rgba[4 * i + 0] = i == 5 ? 1e5f : i * 0.25f;
    passes.linear_rgba[4 * i + 1] = 1.0f / (i + 1);
    passes.linear_rgba[4 * i + 2] = 3.0f;
    passes.linear_rgba[4 * i + 3] = 1.0f;
  }
  std::string error;
  ASSERT_TRUE(write_exr_atomic(dir / "sky.exr", frame, &error)) << error;
  EnvironmentImage image;
  ASSERT_TRUE(read_environment_image(dir / "sky.exr", &image, &error)) << error;
  ASSERT_EQ(image.width_px, 8);
  ASSERT_EQ(image.height_px, 4);
  for (int i = 0; i < 32; ++i) {
    EXPECT_EQ(image.rgb[3 * i + 0], passes.linear_rgba[4 * i + 0]) << i;
    EXPECT_EQ(image.rgb[3 * i + 1], passes.linear_rgba[4 * i + 1]) << i;
    EXPECT_EQ(image.rgb[3 * i + 2], 3.0f) << i;
  }
  passes.linear_rgba[4 * 11 + 1] = std::nanf("");
  ASSERT_TRUE(write_exr_atomic(dir / "nan.exr", frame, &error)) << error;
  EXPECT_FALSE(read_environment_image(dir / "nan.exr", &image, &error));
  EXPECT_NE(error.find("pixel (3, 1) channel G"), std::string::npos) << error;
}

TEST(EnvironmentSetting, NamesTheKeyAndTheFileAndStoresAnAbsolutePath) {
  const auto dir = test::fresh_dir("environment_setting");
  Settings settings;
  auto problems =
      apply_setting_override("render.environment=" + (dir / "nope.hdr").string(), settings);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "render.environment");
  EXPECT_NE(problems[0].message.find("nope.hdr: no such file"), std::string::npos)
      << problems[0].message;
  EXPECT_TRUE(settings.render.environment.empty());  // left as it was

  write_hdr(dir / "sky.hdr", 16, 8, [](int, int) { return Rgb{1, 1, 1}; });
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  problems = apply_setting_override("render.environment=sky.hdr", settings);
  std::filesystem::current_path(cwd);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(std::filesystem::path(settings.render.environment.view()), dir / "sky.hdr");
}

// ---- Renders, against the panorama integrated here ----

// The panorama's frame as frame_constants.h documents it: y the camera's up vector, azimuth 0
// along world z (x when up is near z), turned about y by the rotation.
struct Frame {
  glm::dvec3 x, y, z;
};
Frame panorama_frame(const fr_camera& camera, double rotation_deg) {
  const glm::dvec3 up = glm::normalize(effective_up(camera));
  const glm::dvec3 ref = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  const glm::dvec3 z0 = glm::normalize(ref - up * glm::dot(ref, up));
  const glm::dvec3 x0 = glm::cross(up, z0);
  const double a = rotation_deg * std::numbers::pi / 180;
  return {std::cos(a) * x0 + std::sin(a) * z0, up, std::cos(a) * z0 - std::sin(a) * x0};
}

// The panorama's radiance towards d: (u, v) = (azimuth / 2 pi, polar angle / pi), bilinear
// between pixel centres, columns wrapping, rows clamped.
double radiance(const EnvironmentImage& image, const Frame& f, glm::dvec3 d, int channel) {
  const double phi = std::atan2(glm::dot(d, f.z), glm::dot(d, f.x));
  const double u = phi / (2 * std::numbers::pi) + (phi < 0 ? 1 : 0);
  const double v = std::acos(std::clamp(glm::dot(d, f.y), -1.0, 1.0)) / std::numbers::pi;
  const double fx = u * image.width_px - 0.5, fy = v * image.height_px - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy), ax = fx - x0, ay = fy - y0;
  auto at = [&](int x, int y) {
    x = (x % image.width_px + image.width_px) % image.width_px;
    y = std::clamp(y, 0, image.height_px - 1);
    return static_cast<double>(image.rgb[3 * (y * image.width_px + x) + channel]);
  };
  const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  return (1 - ax) * (1 - ay) * at(ix, iy) + ax * (1 - ay) * at(ix + 1, iy) +
         (1 - ax) * ay * at(ix, iy + 1) + ax * ay * at(ix + 1, iy + 1);
}

RenderSettings with_panorama(RenderSettings s, const std::filesystem::path& file,
                             double rotation_deg) {
  EXPECT_TRUE(s.environment.assign(file.string()));
  s.environment_rotation_deg = static_cast<float>(rotation_deg);
  return s;
}

TEST(EnvironmentRender, RaysThatLeaveShowThePanoramaInTheirExactDirection) {
  const auto dir = test::fresh_dir("environment_background");
  // Smooth in both directions, different in each channel, so a flipped or shifted axis shows.
  const auto file = write_hdr(dir / "ramp.hdr", 32, 16, [](int x, int y) {
    return Rgb{(x + 1) / 8.0f, (y + 1) / 8.0f, ((x * 7 + y * 3) % 16 + 1) / 8.0f};
  });
  EnvironmentImage image;
  std::string error;
  ASSERT_TRUE(read_environment_image(file, &image, &error)) << error;
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  SceneState state = test::dark_state(scene->info);
  // A wide view, so that the pixels see much of the panorama.
  state.camera.fov_deg = 100;
  for (Integrator integrator : {Integrator::Fast, Integrator::Path}) {
    RenderSettings s = with_panorama(test::path_traced(48, 32, 1), file, 40);
    s.integrator = integrator;
    s.disabled_stages = all_optional_stages();
    const FrameImage frame = render_all_samples(renderer, scene->info, state, s, true);
    const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
    const Frame f = panorama_frame(state.camera, 40);
    int misses = 0;
    double worst = 0;
    for (int y = 0; y < s.height_px; ++y)
      for (int x = 0; x < s.width_px; ++x) {
        const size_t i = static_cast<size_t>(y) * s.width_px + x;
        if (std::isfinite(frame.depth[i])) continue;
        ++misses;
        const glm::dvec3 d = camera_ray_dir(rays, x, y);
        for (int c = 0; c < 3; ++c) {
          const double expected = radiance(image, f, d, c);
          worst = std::max(worst, std::abs(frame.linear_rgba[4 * i + c] - expected) / expected);
        }
      }
    EXPECT_GT(misses, 800) << enum_name(integrator);
    // Float azimuths and polar angles: a few 1e-5 of a pixel.
    EXPECT_LT(worst, 2e-3) << enum_name(integrator);
  }
}

TEST(EnvironmentRender, AWhiteBallUnderAUniformPanoramaShowsThePanorama) {
  const auto dir = test::fresh_dir("environment_furnace");
  const auto file = write_hdr(dir / "grey.hdr", 32, 16, [](int, int) {
    return Rgb{0.5f, 0.5f, 0.5f};
  });
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  RenderSettings s = with_panorama(test::path_traced(40, 30, 16), file, 0);
  s.albedo = {1, 1, 1};
  s.hit_threshold_k = 0.05f;
  // The gradient sky black: nothing but the panorama may light the ball.
  s = test::uniform_sky(s, 0);
  const SceneState state = test::dark_state(scene->info);
  const FrameImage frame = render_all_samples(renderer, scene->info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  int hits = 0;
  double sum = 0, worst = 0;
  for (size_t i = 0; i < frame.depth.size(); ++i) {
    const double v = frame.linear_rgba[4 * i];
    if (!std::isfinite(frame.depth[i])) {
      // Where no jittered sample can meet the ball: the panorama exactly.
      const glm::dvec3 d =
          camera_ray_dir(rays, static_cast<int>(i % s.width_px), static_cast<int>(i / s.width_px));
      const double b = glm::dot(rays.eye, d);
      if (glm::dot(rays.eye, rays.eye) - b * b > 1.1 * 1.1) {
        ASSERT_NEAR(v, 0.5, 1e-6);
      }
      continue;
    }
    ++hits;
    sum += v;
    worst = std::max(worst, std::abs(v - 0.5));
  }
  ASSERT_GT(hits, 200);
  // Counted twice it would be 1, half 0.25.
  EXPECT_NEAR(sum / hits, 0.5, 0.005);
  EXPECT_LT(worst, 0.15);
}

TEST(EnvironmentRender, ASmallSunInThePanoramaLightsTheBallAsTheIntegralSays) {
  const auto dir = test::fresh_dir("environment_sun");
  const int w = 64, h = 32;
  // A dim upper half and a 2 x 2-pixel sun of 400 (about a thousandth of the sky's solid angle,
  // most of the light).
  const auto file = write_hdr(dir / "sun.hdr", w, h, [](int x, int y) {
    if (x >= 8 && x < 10 && y >= 9 && y < 11) return Rgb{400, 400, 400};
    return y < h / 2 ? Rgb{0.25f, 0.25f, 0.25f} : Rgb{0, 0, 0};
  });
  EnvironmentImage image;
  std::string error;
  ASSERT_TRUE(read_environment_image(file, &image, &error)) << error;
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const SceneState state = test::dark_state(scene->info);
  const double rotation_deg = 30, albedo = 0.5;
  RenderSettings s = with_panorama(test::path_traced(32, 24, 64), file, rotation_deg);
  s.albedo = {static_cast<float>(albedo), static_cast<float>(albedo), static_cast<float>(albedo)};
  s.hit_threshold_k = 0.05f;
  s = test::uniform_sky(s, 0);
  const FrameImage frame = render_all_samples(renderer, scene->info, state, s, true);

  // The panorama's light, direction by direction, on a grid fine against its pixels (16 x 16
  // directions a pixel, midpoint rule in azimuth and polar angle).
  const Frame f = panorama_frame(state.camera, rotation_deg);
  struct Ray {
    glm::dvec3 d;
    double light;  // radiance x solid angle
  };
  std::vector<Ray> sky;
  const int nu = 16 * w, nv = 16 * h;
  for (int j = 0; j < nv; ++j) {
    const double theta = (j + 0.5) * std::numbers::pi / nv;
    for (int i = 0; i < nu; ++i) {
      const double phi = (i + 0.5) * 2 * std::numbers::pi / nu;
      const glm::dvec3 d = std::sin(theta) * std::cos(phi) * f.x + std::cos(theta) * f.y +
                           std::sin(theta) * std::sin(phi) * f.z;
      const double l = radiance(image, f, d, 0);
      if (l > 0)
        sky.push_back(
            {d, l * std::sin(theta) * (std::numbers::pi / nv) * (2 * std::numbers::pi / nu)});
    }
  }
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  int hits = 0, sunlit = 0;
  double error_sum = 0, expected_sum = 0, rendered_sum = 0, sunlit_error = 0, sunlit_sum = 0;
  // The sun's share: what a pixel gets beyond the dim sky's most (the sky alone gives at most
  // 0.25 x albedo).
  const double sky_most = 0.25 * albedo;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      glm::dvec3 n;
      double cos_view;
      const size_t i = static_cast<size_t>(y) * s.width_px + x;
      // Pixels well inside the silhouette, where the pixel's footprint is one normal.
      if (!test::ball_point(rays, x, y, &n, &cos_view) || cos_view < 0.3 ||
          !std::isfinite(frame.depth[i]))
        continue;
      double irradiance = 0;
      for (const Ray& r : sky) irradiance += r.light * std::max(0.0, glm::dot(n, r.d));
      const double expected = albedo / std::numbers::pi * irradiance;
      const double rendered = frame.linear_rgba[4 * i];
      ++hits;
      error_sum += std::abs(rendered - expected);
      expected_sum += expected;
      rendered_sum += rendered;
      if (expected > 4 * sky_most) {
        ++sunlit;
        sunlit_error += std::abs(rendered - expected);
        sunlit_sum += expected;
      }
    }
  ASSERT_GT(hits, 150);
  ASSERT_GT(sunlit, 50);
  std::printf("whole ball %.4f, mean error %.4f; sunlit %d pixels, mean error %.4f\n",
              rendered_sum / expected_sum, error_sum / expected_sum, sunlit,
              sunlit_error / sunlit_sum);
  // The whole ball's light within 2%; where the sun lights it, each pixel within 5% on average
  // (measured: 7.0%, 3.5%, 1.8% and 0.9% at 16, 64, 256 and 1024 samples, noise that halves as
  // samples quadruple, no bias; drawing pixels by a bound of the 3 x 3 pixels around them instead
  // of the bilinear patch gave 13.6% at 64; found by a cosine-weighted bounce alone, about 1
  // sample in 100 would meet the sun).
  EXPECT_NEAR(rendered_sum / expected_sum, 1.0, 0.02);
  EXPECT_LT(sunlit_error / sunlit_sum, 0.05);
}

}  // namespace
}  // namespace fr
