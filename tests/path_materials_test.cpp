// The path integrator's materials and lights (kernels/material.cl, area_lights.cl, path.cl)
// against answers known without them:
//  - a scene's material function is what the integrator uses, clamped to the material's ranges
//    (an emissive ball under a black sky shows its emission exactly; a base colour of 4 is 1);
//  - a polished metal ball under a uniform sky reflects Schlick's Fresnel of its colour at the
//    exact angle (in double); a rough white metal, the GGX model's albedo at that angle; a rough
//    coloured metal under a light, the GGX BRDF at each pixel's exact normal;
//  - a subsurface medium of albedo 1 loses no light (white furnace), and its colour darkens it;
//  - a light with a size lights a convex surface exactly as a point at its centre does wherever
//    the whole light is above the horizon (the irradiance of a uniform sphere or disc): next-event
//    estimation and bounces that hit the light, weighted by MIS, must add up to that, not to
//    twice it or to one of them.
#include "path_test_support.hpp"
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace fr {
namespace {

// A fine hit threshold: the ball's DE is half the distance, so a hit stops about 2 k t
// pixel-angle short of the sphere, where the radial normal is tilted from the exact one.
RenderSettings path_traced(int width_px, int height_px, int samples) {
  RenderSettings s = test::path_traced(width_px, height_px, samples);
  s.hit_threshold_k = 0.05f;
  return s;
}

using test::ball_point;
using test::dark_state;
using test::light;
using test::set_param;
using test::uniform_sky;

TEST(MaterialFunction, IsWhatTheIntegratorUsesWithinTheMaterialsRanges) {
  Renderer renderer(test::runtime());
  const auto scene = test::material_ball();
  ASSERT_TRUE(scene);
  // Emission (0.2, 0.5, -3) on a black base under a black sky: (0.2, 0.5, 0) on every hit pixel.
  SceneState state = dark_state(scene->info);
  set_param(scene->info, state, "base_color", 0, 0, 0);
  set_param(scene->info, state, "emission", 0.2, 0.5, -3);
  RenderSettings s = uniform_sky(path_traced(40, 30, 1), 0);
  FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  int hits = 0;
  for (size_t i = 0; i < image.depth.size(); ++i) {
    if (!std::isfinite(image.depth[i])) continue;
    ++hits;
    ASSERT_NEAR(image.linear_rgba[4 * i + 0], 0.2, 1e-5);
    ASSERT_NEAR(image.linear_rgba[4 * i + 1], 0.5, 1e-5);
    ASSERT_EQ(image.linear_rgba[4 * i + 2], 0.0f);
  }
  EXPECT_GT(hits, 200);

  // A base colour of 4 is clamped to 1: a white furnace, every hit pixel the sky's 0.5 (a
  // colour of 4 would show 2, energy created).
  set_param(scene->info, state, "base_color", 4, 4, 4);
  set_param(scene->info, state, "emission", 0, 0, 0);
  s = uniform_sky(path_traced(40, 30, 1), 0.5f);
  image = render_all_samples(renderer, scene->info, state, s, true);
  for (size_t i = 0; i < image.depth.size(); ++i) {
    if (std::isfinite(image.depth[i])) {
      ASSERT_NEAR(image.linear_rgba[4 * i], 0.5, 1e-4);
    }
  }
}

// Schlick's approximation for a metal of reflectance f0 at cos(theta).
double schlick(double f0, double cos_theta) {
  return f0 + (1 - f0) * std::pow(1 - cos_theta, 5);
}

TEST(Metal, APolishedBallReflectsSchlicksFresnelOfItsColour) {
  Renderer renderer(test::runtime());
  const auto scene = test::material_ball();
  ASSERT_TRUE(scene);
  SceneState state = dark_state(scene->info);
  const glm::dvec3 colour(0.9, 0.6, 0.2);
  set_param(scene->info, state, "base_color", colour.x, colour.y, colour.z);
  set_param(scene->info, state, "metalness", 3.0 / 2.0);  // above 1: clamped to all metal
  const float sky = 0.5f;
  const RenderSettings s = uniform_sky(path_traced(48, 36, 1), sky);
  const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  int compared = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      glm::dvec3 p;
      double cos_view = 0;
      // Away from the rim, where the estimated normal and the pixel's footprint stray most.
      if (!ball_point(rays, x, y, &p, &cos_view) || cos_view < 0.3) continue;
      ++compared;
      const size_t i = static_cast<size_t>(y) * s.width_px + x;
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(image.linear_rgba[4 * i + k], sky * schlick(colour[k], cos_view), 0.01)
            << x << "," << y << " channel " << k;
    }
  EXPECT_GT(compared, 300);
}

// The directional albedo of a white GGX metal of roughness alpha (single scattering, Smith's
// separable G = G1(i) G1(o)) seen at cos(theta) = mu: the integral over the hemisphere of the
// BRDF times cos, here by the midpoint rule over the unit square that Walter et al.'s sampling of
// D(m) (m.n) maps onto the microfacet normals, each point weighted |i.m| G / (|i.n| |m.n|).
// (Integrated over the outgoing directions instead, with D and G written out, it agrees to 0.3%.)
double ggx_albedo(double mu, double alpha) {
  const auto g1 = [alpha](double c) {
    const double tan2 = (1 - c * c) / (c * c);
    return 2 / (1 + std::sqrt(1 + alpha * alpha * tan2));
  };
  const glm::dvec3 i(std::sqrt(1 - mu * mu), 0, mu);
  constexpr int kSteps = 400;
  double sum = 0;
  for (int a = 0; a < kSteps; ++a)
    for (int b = 0; b < kSteps; ++b) {
      const double u1 = (a + 0.5) / kSteps, u2 = (b + 0.5) / kSteps;
      const double cos_m = 1 / std::sqrt(1 + alpha * alpha * u1 / (1 - u1));
      const double sin_m = std::sqrt(1 - cos_m * cos_m), phi = 2 * M_PI * u2;
      const glm::dvec3 m(sin_m * std::cos(phi), sin_m * std::sin(phi), cos_m);
      const double i_m = glm::dot(i, m);
      const double o_n = 2 * i_m * m.z - i.z;
      if (i_m > 0 && o_n > 0) sum += i_m * g1(mu) * g1(o_n) / (mu * cos_m);
    }
  return sum / (kSteps * kSteps);
}

TEST(Metal, ARoughWhiteMetalReflectsTheMicrofacetModelsAlbedo) {
  // White metal reflects all that its microfacets see; a rough one loses what leaves on a
  // microfacet towards the surface (Smith's G), by the angle: under a uniform sky each pixel
  // shows the sky times the directional albedo at its exact viewing angle. Away from the rim: at
  // grazing angles single samples weigh far more than 1 (their mean does not).
  Renderer renderer(test::runtime());
  const auto scene = test::material_ball();
  ASSERT_TRUE(scene);
  SceneState state = dark_state(scene->info);
  set_param(scene->info, state, "base_color", 1, 1, 1);
  set_param(scene->info, state, "metalness", 1);
  set_param(scene->info, state, "roughness", 0.5);  // alpha 0.25
  const float sky = 0.5f;
  const RenderSettings s = uniform_sky(path_traced(40, 30, 64), sky);
  const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  // The albedo by angle, tabulated and interpolated.
  std::vector<double> albedo(41);
  for (size_t k = 0; k < albedo.size(); ++k) albedo[k] = ggx_albedo(0.5 + 0.5 * k / 40.0, 0.25);
  double shown_sum = 0, expected_sum = 0;
  int compared = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      glm::dvec3 p;
      double cos_view = 0;
      if (!ball_point(rays, x, y, &p, &cos_view) || cos_view < 0.5) continue;
      const double at = (std::min(cos_view, 1.0) - 0.5) * 80;
      const size_t k = std::min<size_t>(static_cast<size_t>(at), 39);
      const double e = albedo[k] + (albedo[k + 1] - albedo[k]) * (at - k);
      const double shown = image.linear_rgba[4 * (static_cast<size_t>(y) * s.width_px + x)];
      ++compared;
      shown_sum += shown;
      expected_sum += sky * e;
      EXPECT_NEAR(shown, sky * e, 0.3 * sky) << x << "," << y;  // 64 samples: noisy
    }
  ASSERT_GT(compared, 200);
  EXPECT_NEAR(shown_sum / compared, expected_sum / compared, 0.01 * sky);
  EXPECT_LT(expected_sum / compared, 0.95 * sky) << "the test sees the shadowing";
}

// What a GGX metal of colour `base` and roughness alpha reflects towards v from a light of
// colour C (lights.cl's unit: a white Lambertian facing it reflects C) from direction l, at
// normal n, channel c: pi C F D G1(v) G1(l) / (4 n.v), with Schlick's F at v.h, D and G1 written
// out from Walter et al. 2007 (eqs. 33 and 34), in double.
double ggx_highlight(glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, double alpha, double base,
                     double c) {
  const double cos_i = glm::dot(n, v), cos_o = glm::dot(n, l);
  if (cos_i <= 0 || cos_o <= 0) return 0;
  const glm::dvec3 h = glm::normalize(v + l);
  const double cos_h = glm::dot(n, h), a2 = alpha * alpha;
  const double d = a2 / (M_PI * std::pow(cos_h * cos_h * (a2 - 1) + 1, 2));
  const auto g1 = [a2](double x) { return 2 / (1 + std::sqrt(1 + a2 * (1 - x * x) / (x * x))); };
  const double f = base + (1 - base) * std::pow(1 - glm::dot(v, h), 5);
  return M_PI * c * f * d * g1(cos_i) * g1(cos_o) / (4 * cos_i);
}

// A ball under a directional light of `color` travelling along `travel` and a black sky (state
// and settings otherwise as given): every pixel that sees the ball at least 0.3 head-on against
// expected(normal where the march stopped, way to the eye, channel), within 0.5% of the peak;
// then under a sun disc of 0.03 radians, 256 samples, the same light over those pixels within 3%.
void expect_highlight_as_modelled(
    const LoadedScene& scene, SceneState state, RenderSettings s, glm::dvec3 travel,
    glm::dvec3 color, const std::function<double(glm::dvec3, glm::dvec3, int)>& expected) {
  Renderer renderer(test::runtime());
  state.lights = {light(FR_LIGHT_DIRECTIONAL, travel, color)};
  s.samples = 1;
  const FrameImage point = render_all_samples(renderer, scene.info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  double peak = 0, worst = 0, point_sum = 0;
  int compared = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      glm::dvec3 n;
      double cos_view = 0;
      if (!ball_point(rays, x, y, &n, &cos_view) || cos_view < 0.3) continue;
      const glm::dvec3 v = -camera_ray_dir(rays, x, y);
      const size_t i = static_cast<size_t>(y) * s.width_px + x;
      // The normal where the march stopped (the depth pass), a hit threshold short of the
      // sphere: the ball's DE is radial, and on the highlight's flank a normal a few thousandths
      // of a radian off changes the BRDF by a percent.
      const glm::dvec3 hit = glm::normalize(rays.eye - v * static_cast<double>(point.depth[i]));
      for (int c = 0; c < 3; ++c) {
        const double e = expected(hit, v, c);
        peak = std::max(peak, e);
        worst = std::max(worst, std::abs(point.linear_rgba[4 * i + c] - e));
      }
      point_sum += point.linear_rgba[4 * i];
      ++compared;
    }
  ASSERT_GT(compared, 300);
  ASSERT_GT(peak, 1.0) << "the view holds the highlight";
  EXPECT_LT(worst, 0.005 * peak);

  state.lights = {light(FR_LIGHT_DIRECTIONAL, travel, color, 0.03)};
  s.samples = 256;
  const FrameImage disc = render_all_samples(renderer, scene.info, state, s, true);
  double disc_sum = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      glm::dvec3 n;
      double cos_view = 0;
      if (!ball_point(rays, x, y, &n, &cos_view) || cos_view < 0.3) continue;
      disc_sum += disc.linear_rgba[4 * (static_cast<size_t>(y) * s.width_px + x)];
    }
  EXPECT_NEAR(disc_sum / point_sum, 1.0, 0.03);
}

// A rough metal ball under one light and a black sky: the highlight is next-event estimation
// through the metal's BRDF. From a direction (a point at infinity) every pixel is that BRDF at
// its exact normal, deterministically; from a small sun disc, sampled by the estimation and met
// by the bounces, the two weighted by MIS, the picture has the same light overall (twice it if
// both counted fully, nothing but noise if the estimation were missing).
TEST(Metal, ARoughMetalShowsALightsHighlightAsTheMicrofacetModelSays) {
  const auto scene = test::material_ball();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  const glm::dvec3 base(0.9, 0.6, 0.3), color(2, 2, 2);
  const double alpha = 0.25;
  set_param(scene->info, state, "base_color", base.x, base.y, base.z);
  set_param(scene->info, state, "metalness", 1);
  set_param(scene->info, state, "roughness", std::sqrt(alpha));
  const glm::dvec3 travel = glm::normalize(glm::dvec3(-0.6, -0.5, -1));
  RenderSettings s = uniform_sky(path_traced(40, 30, 1), 0);
  expect_highlight_as_modelled(*scene, state, s, travel, color,
                               [&](glm::dvec3 hit, glm::dvec3 v, int c) {
                                 return ggx_highlight(hit, v, -travel, alpha, base[c], color[c]);
                               });
}

// The exact unpolarised reflectance of a dielectric, the ray coming from the side of index 1
// into one of index `ior`, at cosine c to the (micro)normal.
double dielectric_fresnel(double c, double ior) {
  const double eta = 1 / ior, sin2_t = eta * eta * (1 - c * c);
  if (sin2_t >= 1) return 1;
  const double cos_t = std::sqrt(1 - sin2_t);
  const double r_s = (eta * c - cos_t) / (eta * c + cos_t);
  const double r_p = (c - eta * cos_t) / (c + eta * cos_t);
  return 0.5 * (r_s * r_s + r_p * r_p);
}

// A rough glass ball under one light and a black sky: the light it reflects is next-event
// estimation through the GGX BRDF times the dielectric's Fresnel reflectance (before, a bounce
// alone could find it, and none finds a direction: no highlight at all). What enters the glass is
// absorbed (a sun disc seen through the ball would add its own light), so a pixel is that
// reflection alone, from a direction exactly; from a small sun disc, met by the bounces too and
// weighted by MIS, the same light overall.
TEST(Glass, RoughGlassReflectsALightAsTheMicrofacetModelSays) {
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  SceneState state = dark_state(scene->info);
  const glm::dvec3 color(20, 20, 20);
  const double alpha = 0.25, ior = 1.5;
  const glm::dvec3 travel = glm::normalize(glm::dvec3(-0.6, -0.5, -1));
  RenderSettings s = uniform_sky(path_traced(40, 30, 1), 0);
  s.transmission = 1;
  s.ior = static_cast<float>(ior);
  s.specular_roughness = static_cast<float>(std::sqrt(alpha));
  s.absorption = 1e4f;
  // ggx_highlight with a white base is the BRDF with F = 1: times the dielectric's F.
  expect_highlight_as_modelled(*scene, state, s, travel, color,
                               [&](glm::dvec3 hit, glm::dvec3 v, int c) {
                                 const glm::dvec3 l = -travel, h = glm::normalize(v + l);
                                 return ggx_highlight(hit, v, l, alpha, 1, color[c]) *
                                        dielectric_fresnel(glm::dot(v, h), ior);
                               });
}

TEST(Subsurface, BelowThePixelsScaleItIsTheDiffuseColour) {
  // A mean free path far below the hit threshold (the scale the walk's entry and exit are
  // resolved to) scatters within the pixel: the convex ball under a uniform sky shows its colour
  // times the sky exactly, as a diffuse ball of that colour does (before the fix, walks that
  // started many free paths deep ran out of scatterings: a black, speckled ball).
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const float sky = 0.5f;
  RenderSettings s = uniform_sky(path_traced(40, 30, 1), sky);
  s.subsurface = 1;
  s.mean_free_path = 1e-5f;
  s.albedo = {0.6f, 0.6f, 0.6f};
  const FrameImage image =
      render_all_samples(renderer, scene->info, dark_state(scene->info), s, true);
  int hits = 0;
  for (size_t i = 0; i < image.depth.size(); ++i) {
    if (!std::isfinite(image.depth[i])) continue;
    ++hits;
    ASSERT_NEAR(image.linear_rgba[4 * i], 0.6 * sky, 1e-4) << i;
  }
  EXPECT_GT(hits, 200);
}

TEST(Subsurface, AMediumOfAlbedoOneLosesNoLight) {
  // The ball all subsurface (render.subsurface = 1) under a uniform sky: light enters, scatters
  // inside, leaves; with a colour of 1 nothing is absorbed, so it shows the sky. A colour of 0.5
  // absorbs: darker, and its colour's hue passes (green kept more than red).
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const float sky = 0.5f;
  RenderSettings s = uniform_sky(path_traced(40, 30, 16), sky);
  s.subsurface = 1;
  s.mean_free_path = 0.05f;  // per bounding radius (2): a tenth of the ball's radius
  s.albedo = {1, 1, 1};
  SceneState state = dark_state(scene->info);
  FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  double sum = 0;
  int hits = 0;
  for (size_t i = 0; i < image.depth.size(); ++i)
    if (std::isfinite(image.depth[i])) {
      ++hits;
      sum += image.linear_rgba[4 * i];
    }
  ASSERT_GT(hits, 200);
  EXPECT_NEAR(sum / hits, sky, 0.01 * sky);

  s.albedo = {0.3f, 0.7f, 0.7f};
  image = render_all_samples(renderer, scene->info, state, s, true);
  double red = 0, green = 0;
  for (size_t i = 0; i < image.depth.size(); ++i)
    if (std::isfinite(image.depth[i])) {
      red += image.linear_rgba[4 * i];
      green += image.linear_rgba[4 * i + 1];
    }
  red /= hits;
  green /= hits;
  // The single-scattering albedos (Chiang et al.'s fit) aim at these colours overall; a walk
  // that kept the colour per scattering instead would be far darker (0.3 to ~0.03).
  EXPECT_NEAR(red, 0.3 * sky, 0.35 * 0.3 * sky);
  EXPECT_NEAR(green, 0.7 * sky, 0.2 * 0.7 * sky);
}

// A light with a size at `where` (a sphere of `radius`, or a sun of angular radius `radius`
// travelling along `where`) lights the diffuse unit ball (albedo 0.8) under a black sky; where the
// whole light is above a point's horizon, the point shows 0.8 x colour x cos(normal, axis) — the
// irradiance of a uniform sphere or disc is that of a point at its centre — and the test
// compares every such pixel.
void expect_like_a_point(fr_light_kind kind, glm::dvec3 where, double radius) {
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  const glm::dvec3 colour(0.9, 0.7, 0.5);
  state.lights = {light(kind, where, colour, radius)};
  RenderSettings s = uniform_sky(path_traced(40, 30, 64), 0);
  s.albedo = {0.8f, 0.8f, 0.8f};
  const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
  const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
  int compared = 0;
  double error = 0, error_doubled = 0;
  for (int y = 0; y < s.height_px; ++y)
    for (int x = 0; x < s.width_px; ++x) {
      glm::dvec3 p;
      double cos_view = 0;
      if (!ball_point(rays, x, y, &p, &cos_view) || cos_view < 0.3) continue;
      glm::dvec3 axis;
      double sin_max;
      if (kind == FR_LIGHT_POINT) {
        axis = glm::normalize(where - p);
        sin_max = radius / glm::length(where - p);
      } else {
        axis = -glm::normalize(where);
        sin_max = std::sin(radius);
      }
      const double cos_axis = glm::dot(p, axis);
      // The whole light above the horizon, and every direction to it above cos 0.3 (as in
      // path_integrator_test's Lambert test: a shadow ray that grazes the ball passes within
      // the hard shadow's margin, which this DE, half the distance, halves again).
      if (cos_axis < sin_max + 0.3) continue;
      ++compared;
      const size_t i = static_cast<size_t>(y) * s.width_px + x;
      for (int k = 0; k < 3; ++k) {
        const double expected = 0.8 * colour[k] * cos_axis;
        const double shown = image.linear_rgba[4 * i + k];
        EXPECT_NEAR(shown, expected, 0.04) << x << "," << y << " channel " << k << " cos(axis) "
                                           << cos_axis << " cos(view) " << cos_view;
        error += std::abs(shown - expected);
        error_doubled += std::abs(shown - 2 * expected);
      }
    }
  EXPECT_GT(compared, 100);
  EXPECT_LT(error / (3 * compared), 0.01) << "mean error";
  EXPECT_GT(error_doubled, 10 * error) << "the measure tells a light counted twice apart";
}

TEST(AreaLight, ASphereLightsLikeAPointAtItsCentreAboveTheHorizon) {
  // Radius 0.6 at 5.2 from the ball's centre: a cone of half-angle ~7 degrees.
  expect_like_a_point(FR_LIGHT_POINT, {3, 3, 3}, 0.6);
}

TEST(AreaLight, ASunDiscLightsLikeADirectionAboveTheHorizon) {
  expect_like_a_point(FR_LIGHT_DIRECTIONAL, {-1, -0.6, -0.8}, 0.15);
}

TEST(AreaLight, ASphereCastsAPenumbraAPointDoesNot) {
  // The ball's own terminator is the shadow's edge. Just behind it, where the light's centre is
  // below the horizon but part of the sphere above it, a sphere light still lights the surface
  // and a point light (of the same centre) does not.
  Renderer renderer(test::runtime());
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const glm::dvec3 centre(4, 0, 0);
  int between_sphere = 0, between_point = 0;
  for (double radius : {1.5, 0.0}) {
    SceneState state = make_default_state(scene->info);
    state.lights = {light(FR_LIGHT_POINT, centre, {1, 1, 1}, radius)};
    RenderSettings s = uniform_sky(path_traced(48, 36, 64), 0);
    s.albedo = {1, 1, 1};
    const FrameImage image = render_all_samples(renderer, scene->info, state, s, true);
    const CameraRays rays = make_camera_rays(state.camera, s.width_px, s.height_px);
    for (int y = 0; y < s.height_px; ++y)
      for (int x = 0; x < s.width_px; ++x) {
        glm::dvec3 p;
        double cos_view = 0;
        if (!ball_point(rays, x, y, &p, &cos_view) || cos_view < 0.3) continue;
        // Just behind the point light's terminator: no light from the centre, part of the sphere.
        const double cos_axis = glm::dot(p, glm::normalize(centre - p));
        if (cos_axis > -0.02 || cos_axis < -0.12) continue;
        const double shown = image.linear_rgba[4 * (static_cast<size_t>(y) * s.width_px + x)];
        (radius > 0 ? between_sphere : between_point) += shown > 0.005;
      }
  }
  EXPECT_GT(between_sphere, 5) << "the sphere lights points its centre cannot";
  EXPECT_EQ(between_point, 0);
}

}  // namespace
}  // namespace fr
