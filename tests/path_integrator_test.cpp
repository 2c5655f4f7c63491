// The path integrator (render.integrator = "path", kernels/path.cl) against answers known without
// it: the white furnace (a diffuse surface under a uniform sky of radiance L shows albedo x L
// where it sees only sky, and L everywhere, however concave, when its albedo is 1: no energy is
// created or lost), Lambert's law for a directional light on the unit ball (the exact normal from
// the pixel's ray, in double), and determinism (a pixel's samples depend only on the pixel, the
// sample index and the seed, so an image rendered in bands is the whole image's, byte for byte),
// convergence (the error against a long render falls as 1 / sqrt(samples)), glass (invisible
// under a uniform sky when it absorbs nothing; Beer-Lambert along the exact chord when it does;
// the sky refracted where geometric optics says), and emission.
#include "path_test_support.hpp"
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace fr {
namespace {

// One directional light (travelling along `direction`) of colour `rgb`, replacing the scene's.
fr_light directional(glm::dvec3 direction, glm::dvec3 rgb) {
  return test::light(FR_LIGHT_DIRECTIONAL, direction, rgb);
}

using test::dark_state;
using test::path_traced;

// Path tracing under a uniform sky of radiance `sky`, with no light (one of intensity 0: without
// any light the host adds one).
RenderSettings furnace(float albedo, float sky, int width_px, int height_px) {
  RenderSettings s = test::uniform_sky(path_traced(width_px, height_px, 1), sky);
  s.albedo = {albedo, albedo, albedo};
  return s;
}

struct PixelStats {
  int hits = 0;
  double mean = 0;   // of the red channel over the hit pixels
  double worst = 0;  // largest |value - expected| among them
  int far_off = 0;   // pixels more than `tolerance` from the expected value
};

PixelStats hit_pixel_stats(const FrameImage& image, double expected, double tolerance) {
  PixelStats st;
  double sum = 0;
  for (size_t i = 0; i < image.depth.size(); ++i) {
    if (!std::isfinite(image.depth[i])) continue;
    ++st.hits;
    for (int c = 0; c < 3; ++c) {
      const double v = image.linear_rgba[4 * i + c];
      if (c == 0) sum += v;
      st.worst = std::max(st.worst, std::abs(v - expected));
      if (std::abs(v - expected) > tolerance) ++st.far_off;
    }
  }
  st.mean = st.hits > 0 ? sum / st.hits : 0;
  return st;
}

TEST(WhiteFurnace, AConvexDiffuseBallShowsAlbedoTimesTheSky) {
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const float sky = 0.6f;
  for (float albedo : {1.0f, 0.5f}) {
    SCOPED_TRACE("albedo " + std::to_string(albedo));
    RenderSettings s = furnace(albedo, sky, 48, 32);
    const FrameImage image =
        render_all_samples(renderer, scene->info, dark_state(scene->info), s, true);
    // Every bounce off a convex surface leaves it for the sky: albedo x L exactly, each sample.
    const PixelStats st = hit_pixel_stats(image, albedo * sky, 0.01);
    EXPECT_GT(st.hits, 200) << "the ball is in view";
    EXPECT_NEAR(st.mean, albedo * sky, 0.002 * sky);
    EXPECT_LE(st.far_off, st.hits / 100) << "worst " << st.worst;
    // The sky itself, where the rays miss.
    for (size_t i = 0; i < image.depth.size(); ++i) {
      if (std::isfinite(image.depth[i])) continue;
      ASSERT_NEAR(image.linear_rgba[4 * i], sky, 1e-6);
    }
  }
}

TEST(WhiteFurnace, AConcaveSurfaceOfAlbedoOneDisappears) {
  // A Menger sponge of albedo 1 under a uniform sky: light bounces between its faces, none is
  // absorbed, so every pixel shows the sky's radiance (paths longer than the bounce limit are
  // cut: a small loss, which this many bounces keeps below the tolerance).
  Renderer renderer(test::runtime());
  const auto scene = test::plain_sponge();
  ASSERT_TRUE(scene);
  const float sky = 0.5f;
  RenderSettings s = furnace(1.0f, sky, 40, 30);
  s.path_max_bounces = 64;
  s.samples = 16;
  const FrameImage image =
      render_all_samples(renderer, scene->info, dark_state(scene->info), s, true);
  const PixelStats st = hit_pixel_stats(image, sky, 0.05 * sky);
  EXPECT_GT(st.hits, 300) << "the sponge is in view";
  EXPECT_NEAR(st.mean, sky, 0.01 * sky);
  EXPECT_LE(st.far_off, st.hits / 50) << "worst " << st.worst;

  // Albedo 0.5: darker than one bounce's 0.5 L nowhere, and darker than L everywhere; crevices,
  // which see more of the sponge than of the sky, darker than faces in the open.
  s.albedo = {0.5f, 0.5f, 0.5f};
  const FrameImage half =
      render_all_samples(renderer, scene->info, dark_state(scene->info), s, true);
  const PixelStats h = hit_pixel_stats(half, 0.5 * sky, sky);
  EXPECT_LT(h.mean, 0.5 * sky) << "some light is lost at every bounce, and a crevice sees less sky";
  EXPECT_GT(h.mean, 0.25 * sky);
}

// Glass of index 1.5 that absorbs nothing, under a uniform sky: every path refracts and reflects
// until it leaves for the sky, so every pixel shows the sky's radiance (the Fresnel odds and
// Snell's law keep energy: a reflectance that did not sum with the transmittance to 1, or a
// refraction that lost paths inside, would show), on the ball and in the sponge's crevices.
TEST(Glass, ThatAbsorbsNothingIsInvisibleUnderAUniformSky) {
  Renderer renderer(test::runtime());
  for (const auto& scene : {test::unit_ball(), test::plain_sponge()}) {
    ASSERT_TRUE(scene);
    SCOPED_TRACE(scene->info.id);
    const float sky = 0.4f;
    RenderSettings s = furnace(0.7f, sky, 40, 30);
    s.transmission = 1;
    s.ior = 1.5f;
    // Light can be trapped long by total internal reflection in the sponge's glass: at 64
    // interactions 7% of it was still inside (cut paths are the one loss the test allows).
    s.path_max_bounces = 1000;
    s.samples = 4;
    // A fine hit threshold: a ray goes through the glass's surface from 2 thresholds off it, and
    // at this image's coarse one that would be more than the sponge's thinnest walls.
    s.hit_threshold_k = 0.05f;
    const FrameImage image =
        render_all_samples(renderer, scene->info, dark_state(scene->info), s, true);
    const PixelStats st = hit_pixel_stats(image, sky, 0.05 * sky);
    EXPECT_GT(st.hits, 200);
    EXPECT_NEAR(st.mean, sky, 0.01 * sky);
    EXPECT_LE(st.far_off, st.hits / 50) << "worst " << st.worst;
  }
}

// Glass that does not bend light (index 1: no refraction, no reflection) but absorbs: each pixel
// of the ball passes exp(-sigma x chord) of the uniform sky behind it (Beer-Lambert), the chord
// the pixel's ray cuts through the unit sphere, in double; sigma = render.absorption per bounding
// radius times 1 - the colour (0.5 grey: half of it).
TEST(Glass, AbsorbsAsBeerLambertAlongTheChord) {
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const float sky = 0.8f;
  RenderSettings s = furnace(0.5f, sky, 48, 36);
  s.transmission = 1;
  s.ior = 1;
  s.absorption = 3;
  s.hit_threshold_k = 0.05f;
  const SceneState state = dark_state(scene->info);
  const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  const double sigma = 3 / state.bounding_radius * (1 - 0.5);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  int compared = 0;
  double darkest = 1;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      const double b = glm::dot(rays.eye, d), c = glm::dot(rays.eye, rays.eye) - 1;
      const double disc = b * b - c;
      if (disc < 0.2) continue;  // away from the silhouette, where a pixel straddles the edge
      const double chord = 2 * std::sqrt(disc);
      const double expected = sky * std::exp(-sigma * chord);
      darkest = std::min(darkest, expected);
      ++compared;
      const size_t i = static_cast<size_t>(y) * s.width_px + x;
      ASSERT_NEAR(image.linear_rgba[4 * i], expected, 0.01) << x << "," << y << " chord " << chord;
    }
  EXPECT_GT(compared, 200);
  EXPECT_LT(darkest, 0.25 * sky) << "the test covers strong absorption";
}

// The sky's radiance in direction d (shade.cl's gradient: horizon to zenith with the camera's up).
double sky_radiance(const RenderSettings& s, const CameraRays& rays, const glm::dvec3& d) {
  const double up = std::clamp(glm::dot(d, rays.up), 0.0, 1.0);
  return s.sky_horizon[0] * (1 - up) + s.sky_zenith[0] * up;
}

// Unpolarised Fresnel reflectance for a ray leaving index n1 into n2 at cos(theta_i), and the
// refracted direction (nothing beyond the critical angle). `n` faces the incoming ray.
double fresnel(double eta, double cos_i, double* cos_t) {
  const double sin2_t = eta * eta * (1 - cos_i * cos_i);
  if (sin2_t >= 1) return 1;
  *cos_t = std::sqrt(1 - sin2_t);
  const double rs = (eta * cos_i - *cos_t) / (eta * cos_i + *cos_t);
  const double rp = (cos_i - eta * *cos_t) / (cos_i + eta * *cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

// A glass ball (index 1.5, no absorption) in front of the sky's gradient, which it turns upside
// down: each pixel's expected radiance from geometric optics in double — reflected at the entry
// with Fresnel's odds, else refracted, then at each internal hit of the unit sphere refracted out
// (towards the sky behind) or reflected in again, summed over 30 internal bounces — against the
// integrator's mean of 256 samples.
TEST(Glass, ABallRefractsTheSkyWhereGeometricOpticsSays) {
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  RenderSettings s = path_traced(40, 30, 256);
  s.sky_horizon = {0.9f, 0.9f, 0.9f};
  s.sky_zenith = {0.1f, 0.1f, 0.1f};
  s.transmission = 1;
  s.ior = 1.5f;
  s.path_max_bounces = 40;
  s.hit_threshold_k = 0.05f;
  const SceneState state = dark_state(scene->info);
  const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  int compared = 0;
  double off_optics = 0, off_straight = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      const double b = glm::dot(rays.eye, d), c = glm::dot(rays.eye, rays.eye) - 1;
      if (b * b - c < 0.3) continue;  // away from the rim, where Fresnel's odds change fastest
      glm::dvec3 p = rays.eye + d * (-b - std::sqrt(b * b - c));
      glm::dvec3 n = p;  // unit: the outward normal, facing the incoming ray
      double cos_i = -glm::dot(d, n), cos_t = 0;
      const double f_in = fresnel(1 / 1.5, cos_i, &cos_t);
      double expected = f_in * sky_radiance(s, rays, d + 2 * cos_i * n);
      glm::dvec3 dir = glm::normalize(d / 1.5 + (cos_i / 1.5 - cos_t) * n);
      double carried = 1 - f_in;
      for (int k = 0; k < 30 && carried > 1e-6; ++k) {
        p = p + dir * (-2 * glm::dot(p, dir));  // the chord to the sphere's far side
        n = -p;                                 // inward: facing the ray inside
        cos_i = -glm::dot(dir, n);
        const double f_out = fresnel(1.5, cos_i, &cos_t);
        if (f_out < 1)
          expected += carried * (1 - f_out) *
                      sky_radiance(s, rays, glm::normalize(dir * 1.5 + (1.5 * cos_i - cos_t) * n));
        carried *= f_out;
        dir = dir + 2 * cos_i * n;
      }
      const double straight = sky_radiance(s, rays, d);
      ++compared;
      const size_t i = static_cast<size_t>(y) * s.width_px + x;
      off_optics += std::abs(image.linear_rgba[4 * i] - expected);
      off_straight += std::abs(image.linear_rgba[4 * i] - straight);
      ASSERT_NEAR(image.linear_rgba[4 * i], expected, 0.04)
          << x << "," << y << " (the sky straight behind: " << straight << ")";
    }
  EXPECT_GT(compared, 150);
  // And the test tells glass from no glass: the sky straight through is much further off.
  EXPECT_GT(off_straight, 5 * off_optics)
      << "mean error " << off_optics / compared << ", straight through " << off_straight / compared;
}

// An emissive ball under a black sky with no light: each pixel shows what the surface gives off,
// emission x colour, exactly (its own light, bounced, leaves the convex ball for the black sky).
TEST(Emission, AGlowingBallShowsItsOwnLight) {
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  RenderSettings s = furnace(0.6f, 0.0f, 40, 30);
  s.emission = 2;
  const FrameImage image =
      render_all_samples(renderer, scene->info, dark_state(scene->info), s, true);
  const PixelStats st = hit_pixel_stats(image, 2 * 0.6, 0.01);
  EXPECT_GT(st.hits, 200);
  EXPECT_NEAR(st.mean, 1.2, 0.005);
  EXPECT_LE(st.far_off, st.hits / 100) << "worst " << st.worst;
}

// Radiance from a directional light on a diffuse ball under a black sky: albedo x cos(theta) x
// colour (shade.cl's convention: the colour is what a white surface facing the light reflects),
// theta from the exact normal where the pixel's ray meets the unit sphere.
TEST(DirectLight, FollowsLambertsLawOnTheBall) {
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  RenderSettings s = furnace(0.8f, 0.0f, 64, 48);
  // A fine hit threshold: this DE is half the distance, so a hit stops about 2 k t pixel-angle
  // short of the sphere, where the radial normal is tilted from the exact one.
  s.hit_threshold_k = 0.05f;
  const glm::dvec3 travel = glm::normalize(glm::dvec3(-1.0, -0.3, 0.0));
  const glm::dvec3 colour(0.9, 0.6, 0.3);
  SceneState state = make_default_state(scene->info);
  state.lights = {directional(travel, colour)};
  const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  int compared = 0, lit = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      const double b = glm::dot(rays.eye, d), c = glm::dot(rays.eye, rays.eye) - 1;
      if (b * b - c <= 0) continue;
      const glm::dvec3 n = rays.eye + d * (-b - std::sqrt(b * b - c));
      // Away from the silhouette, where a pixel's footprint straddles two answers, and from the
      // terminator: a shadow ray that grazes the ball passes within the hard shadow's margin (a
      // few hit thresholds, which this DE, half the distance, halves again) and counts as blocked.
      const double cos_view = -glm::dot(n, d), cos_light = -glm::dot(n, travel);
      if (cos_view < 0.3 || std::abs(cos_light) < 0.3) continue;
      ++compared;
      lit += cos_light > 0;
      const size_t i = static_cast<size_t>(y) * s.width_px + x;
      for (int k = 0; k < 3; ++k) {
        const double expected = 0.8 * std::max(0.0, cos_light) * colour[k];
        ASSERT_NEAR(image.linear_rgba[4 * i + k], expected, 0.02)
            << x << "," << y << " channel " << k << " (cos " << cos_light << ")";
      }
    }
  EXPECT_GT(compared, 200);
  EXPECT_GT(lit, compared / 4);
  EXPECT_LT(lit, compared * 3 / 4) << "both sides of the terminator";
}

// The Mandelbulb path-traced with a sun and a sky: an image in two bands (poster rendering) and
// the whole image agree byte for byte; another seed gives other noise, the same seed the same.
TEST(PathIntegrator, IsAFunctionOfPixelSampleAndSeed) {
  Renderer renderer(test::runtime());
  const auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  const SceneState state = make_default_state(scene->info);
  const RenderSettings whole_settings = path_traced(40, 24, 2);
  const FrameImage whole = render_all_samples(renderer, scene->info, state, whole_settings, true);
  const int split = 11;  // not a multiple of the tile height
  for (const auto& [y0, rows] : {std::pair{0, split}, std::pair{split, 24 - split}}) {
    RenderSettings band = whole_settings;
    band.window = ImageWindow{40, 24, 0, y0};
    band.height_px = rows;
    const FrameImage part = render_all_samples(renderer, scene->info, state, band, true);
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < 40; ++x) {
        const size_t a = static_cast<size_t>(y) * 40 + x, b = static_cast<size_t>(y0 + y) * 40 + x;
        for (int c = 0; c < 4; ++c)
          ASSERT_EQ(part.linear_rgba[4 * a + c], whole.linear_rgba[4 * b + c])
              << "pixel " << x << "," << y0 + y;
      }
  }
  RenderSettings reseeded = whole_settings;
  reseeded.seed = 7;
  const FrameImage other = render_all_samples(renderer, scene->info, state, reseeded, true);
  const FrameImage again = render_all_samples(renderer, scene->info, state, reseeded, true);
  EXPECT_EQ(other.linear_rgba, again.linear_rgba);
  EXPECT_NE(other.linear_rgba, whole.linear_rgba);
}

// The error of a path-traced image falls as 1 / sqrt(samples): against a 2048-sample reference
// of another seed (independent noise), the RMS error at 8, 32 and 128 samples lies on a line of
// slope -1/2 in log-log, within 20% (the reference's own noise adds about 3% to the last error).
TEST(PathIntegrator, ErrorFallsAsOneOverTheSquareRootOfSamples) {
  Renderer renderer(test::runtime());
  const auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  const SceneState state = make_default_state(scene->info);
  RenderSettings s = path_traced(24, 16, 2048);
  s.seed = 1;
  const FrameImage reference = render_all_samples(renderer, scene->info, state, s, true);
  s.seed = 0;
  std::vector<double> log_n, log_error;
  for (int n : {8, 32, 128}) {
    s.samples = n;
    const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
    double sum = 0;
    for (size_t i = 0; i < image.linear_rgba.size(); ++i)
      if (i % 4 != 3) sum += std::pow(image.linear_rgba[i] - reference.linear_rgba[i], 2.0);
    const double rms = std::sqrt(sum / (image.linear_rgba.size() * 3 / 4));
    ASSERT_GT(rms, 0) << n << " samples: noise is expected";
    log_n.push_back(std::log(n));
    log_error.push_back(std::log(rms));
  }
  // Least-squares slope of log(error) against log(samples).
  const double mx = (log_n[0] + log_n[1] + log_n[2]) / 3;
  const double my = (log_error[0] + log_error[1] + log_error[2]) / 3;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < 3; ++i) {
    sxy += (log_n[i] - mx) * (log_error[i] - my);
    sxx += (log_n[i] - mx) * (log_n[i] - mx);
  }
  EXPECT_NEAR(sxy / sxx, -0.5, 0.1) << "errors " << std::exp(log_error[0]) << ", "
                                    << std::exp(log_error[1]) << ", " << std::exp(log_error[2]);
}

}  // namespace
}  // namespace fr
