#include "render/frame_constants.hpp"

#include <glm/geometric.hpp>

#include <cstddef>

namespace fr {

// The kernels read this struct with OpenCL C's layout rules; with only 4-byte fields both sides
// agree, and these checks keep it so.
static_assert(sizeof(fr_frame_constants) == 240, "fr_frame_constants layout changed");
static_assert(sizeof(fr_frame_constants) % 16 == 0);
static_assert(offsetof(fr_frame_constants, eye) == 0);
static_assert(offsetof(fr_frame_constants, to_light) == 64);
static_assert(offsetof(fr_frame_constants, width) == 176);
static_assert(offsetof(fr_frame_constants, pixel_angle_rad) == 192);
static_assert(offsetof(fr_frame_constants, reserved) == 228);

namespace {
void put(float out[4], glm::dvec3 v) {
  out[0] = static_cast<float>(v.x);
  out[1] = static_cast<float>(v.y);
  out[2] = static_cast<float>(v.z);
  out[3] = 0;
}
void put(float out[4], const std::array<float, 3>& v) {
  out[0] = v[0];
  out[1] = v[1];
  out[2] = v[2];
  out[3] = 0;
}
}  // namespace

fr_frame_constants make_frame_constants(const CameraRays& rays, const SceneState& state,
                                        const RenderSettings& s) {
  fr_frame_constants fc{};
  put(fc.eye, rays.eye);
  put(fc.first_pixel_dir, rays.first_pixel_dir);
  put(fc.pixel_step_x, rays.pixel_step_x);
  put(fc.pixel_step_y, rays.pixel_step_y);

  // The first directional light is the key light; without one, light from above-behind.
  glm::dvec3 to_light = glm::normalize(glm::dvec3(0.5, 1.0, 0.6));
  glm::dvec3 light_color(1.0);
  for (const fr_light& l : state.lights) {
    if (l.kind != FR_LIGHT_DIRECTIONAL) continue;
    glm::dvec3 dir(l.vector[0], l.vector[1], l.vector[2]);
    if (glm::length(dir) > 0) to_light = -glm::normalize(dir);
    light_color = glm::dvec3(l.color[0], l.color[1], l.color[2]) * l.intensity;
    break;
  }
  put(fc.to_light, to_light);
  put(fc.light_color, light_color);
  put(fc.ambient_color, s.ambient);
  put(fc.albedo, s.albedo);
  put(fc.sky_zenith, s.sky_zenith);
  put(fc.sky_horizon, s.sky_horizon);
  put(fc.sky_up,
      glm::normalize(glm::dvec3(state.camera.up[0], state.camera.up[1], state.camera.up[2])));

  fc.width = rays.width_px;
  fc.height = rays.height_px;
  fc.max_steps = s.max_steps;
  fc.shadow_max_steps = s.shadow_max_steps;
  fc.pixel_angle_rad = static_cast<float>(rays.pixel_angle_rad);
  fc.hit_threshold_k = s.hit_threshold_k;
  fc.max_distance = s.max_distance;
  fc.bounding_radius = static_cast<float>(state.bounding_radius);
  fc.step_scale = s.step_scale;
  fc.ao_strength = s.ao_strength;
  fc.shadow_softness = s.shadow_softness;
  fc.specular_strength = s.specular_strength;
  fc.specular_power = s.specular_power;
  return fc;
}

}  // namespace fr
