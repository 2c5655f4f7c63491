// path_test_support.hpp — small helpers of the path integrator's tests (path_integrator_test,
// path_materials_test, environment_test): settings, lights and the unit ball's exact geometry.
#pragma once

#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/render_settings.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace fr::test {

// Path tracing at w x h, `samples` samples a pixel, the rest as by default.
inline RenderSettings path_traced(int width_px, int height_px, int samples) {
  RenderSettings s;
  s.integrator = Integrator::Path;
  s.width_px = width_px;
  s.height_px = height_px;
  s.samples = samples;
  return s;
}

// The sky gradient made uniform: radiance `sky` from every direction.
inline RenderSettings uniform_sky(RenderSettings s, float sky) {
  s.sky_zenith = s.sky_horizon = {sky, sky, sky};
  return s;
}

// A light of colour `rgb` (intensity 1): `vector` is a directional light's direction of travel
// or a point light's position; `radius` its size (0: a point).
inline fr_light light(fr_light_kind kind, glm::dvec3 vector, glm::dvec3 rgb, double radius = 0) {
  fr_light l{};
  l.struct_size = sizeof l;
  l.kind = kind;
  for (int k = 0; k < 3; ++k) {
    l.vector[k] = vector[k];
    l.color[k] = rgb[k];
  }
  l.intensity = 1;
  l.radius = radius;
  return l;
}

// The scene's defaults with no light: one of colour 0 (without any, the renderer adds its own).
inline SceneState dark_state(const SceneInfo& info) {
  SceneState state = make_default_state(info);
  state.lights = {light(FR_LIGHT_DIRECTIONAL, {0, -1, 0}, {0, 0, 0})};
  return state;
}

inline void set_param(const SceneInfo& info, SceneState& state, const std::string& key, double x,
                      double y = 0, double z = 0) {
  for (size_t i = 0; i < info.params.size(); ++i)
    if (info.params[i].key == key) {
      state.params[i].v[0] = x;
      state.params[i].v[1] = y;
      state.params[i].v[2] = z;
      return;
    }
  FAIL() << "no parameter " << key;
}

// Where pixel (x, y)'s central ray meets the unit sphere: the point (= its outward normal) and
// the cosine between the normal and the way back to the eye; false where it misses.
inline bool ball_point(const CameraRays& rays, int x, int y, glm::dvec3* p, double* cos_view) {
  const glm::dvec3 d = camera_ray_dir(rays, x, y);
  const double b = glm::dot(rays.eye, d), c = glm::dot(rays.eye, rays.eye) - 1;
  if (b * b - c <= 0) return false;
  *p = rays.eye + d * (-b - std::sqrt(b * b - c));
  *cos_view = -glm::dot(*p, d);
  return true;
}

}  // namespace fr::test
