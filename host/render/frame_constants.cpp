#include "render/frame_constants.hpp"
#include "scene/camera_up.hpp"
#include "scene/vec3.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace fr {

static_assert(FR_MAX_LIGHTS == FR_MAX_SCENE_LIGHTS,
              "the kernel holds every light a scene may declare");

static_assert(FR_KERNEL_LIGHT_DIRECTIONAL == FR_LIGHT_DIRECTIONAL &&
              FR_KERNEL_LIGHT_POINT == FR_LIGHT_POINT);

// The kernels read this struct with OpenCL C's layout rules; with only 4-byte fields both sides
// agree, and these checks keep it so.
static_assert(sizeof(fr_frame_constants) == 1064, "fr_frame_constants layout changed");
static_assert(offsetof(fr_frame_constants, first_pixel_dir) == 0);
static_assert(offsetof(fr_frame_constants, light_vector) == 96);
static_assert(offsetof(fr_frame_constants, light_kind) == 352);
static_assert(offsetof(fr_frame_constants, ambient_color) == 448);
static_assert(offsetof(fr_frame_constants, width) == 560);
static_assert(offsetof(fr_frame_constants, pixel_angle_rad) == 592);
static_assert(offsetof(fr_frame_constants, relaxation) == 664);
static_assert(offsetof(fr_frame_constants, fog_scale) == 676);
static_assert(offsetof(fr_frame_constants, first_pixel_dir_lo) == 680);
static_assert(offsetof(fr_frame_constants, ray_start) == 728);
static_assert(offsetof(fr_frame_constants, start_scale) == 824);
static_assert(offsetof(fr_frame_constants, ao_reference_steps) == 832);
static_assert(offsetof(fr_frame_constants, cone_blocks_y) == 852);
static_assert(offsetof(fr_frame_constants, path_max_bounces) == 892);
static_assert(offsetof(fr_frame_constants, absorption) == 904);
static_assert(offsetof(fr_frame_constants, light_radius) == 912);
static_assert(offsetof(fr_frame_constants, aperture_blades) == 960);
static_assert(offsetof(fr_frame_constants, env_axes) == 964);
static_assert(offsetof(fr_frame_constants, env_intensity) == 1020);
static_assert(offsetof(fr_frame_constants, hit_threshold_abs) == 1024);
static_assert(offsetof(fr_frame_constants, bounding_centre) == 1028);
static_assert(offsetof(fr_frame_constants, bounding_centre_lo) == 1044);
static_assert(offsetof(fr_frame_constants, threshold_floor_scale) == 1060);
namespace {
void put(float out[4], glm::dvec3 v) {
  out[0] = static_cast<float>(v.x);
  out[1] = static_cast<float>(v.y);
  out[2] = static_cast<float>(v.z);
  out[3] = 0;
}
void put(float out[4], const std::array<float, 3>& v) {
  put(out, glm::dvec3(v[0], v[1], v[2]));
}
// A double as its rounded float (hi) and what the rounding lost (lo): hi + lo in double is the
// value to about 48 bits, so the double kernel gets the camera in double. The rounded value
// goes through a volatile: GCC 12 at -O3 vectorised the vector version of this into
// lo = v - v = 0 (it reused the unrounded double), which silently made double renders of deep
// zooms float-precise (frame_constants_test catches it).
void put_hi_lo(float& hi, float& lo, double v) {
  volatile float rounded = static_cast<float>(v);
  hi = rounded;
  lo = static_cast<float>(v - static_cast<double>(rounded));
}
void put_hi_lo(float hi[4], float lo[4], glm::dvec3 v) {
  for (int a = 0; a < 3; ++a) put_hi_lo(hi[a], lo[a], v[a]);
  hi[3] = lo[3] = 0;
}

// The start plane of primary rays (frame_constants.h): the eye's distance along the view to
// just before the bounding sphere, as a multiple of the direction vectors' component along the
// view (which the camera's image plane, render/camera.hpp, keeps the same for every pixel). 0
// (start at the eye) when the eye is within the bounds, or when a thin lens moves ray origins off
// the eye.
double start_scale(const CameraRays& rays, glm::dvec3 bounding_centre, double bounding_radius,
                   float aperture_radius) {
  if (aperture_radius > 0) return 0;
  const double ahead = glm::dot(bounding_centre - rays.eye, rays.forward) - 1.001 * bounding_radius;
  const double along = glm::dot(rays.first_pixel_dir, rays.forward);
  if (ahead <= 0 || along <= 0) return 0;
  return ahead / along;
}
}  // namespace

std::array<double, 2> sample_jitter(int i) {
  if (i <= 0) return {0, 0};
  const double g = 1.32471795724474602596;  // plastic number
  double x = 0.5 + i / g, y = 0.5 + i / (g * g);
  return {x - std::floor(x) - 0.5, y - std::floor(y) - 0.5};
}

double threshold_floor_scale(double eye_distance, double bounding_radius) {
  return std::min(std::max(eye_distance, bounding_radius / 1024), bounding_radius);
}

fr_frame_constants make_frame_constants(const CameraRays& rays, const SceneState& state,
                                        const RenderSettings& s, int sample_index,
                                        glm::dvec3 bounding_centre) {
  fr_frame_constants fc{};
  put_hi_lo(fc.bounding_centre, fc.bounding_centre_lo, bounding_centre);
  put_hi_lo(fc.first_pixel_dir, fc.first_pixel_dir_lo, rays.first_pixel_dir);
  put_hi_lo(fc.pixel_step_x, fc.pixel_step_x_lo, rays.pixel_step_x);
  put_hi_lo(fc.pixel_step_y, fc.pixel_step_y_lo, rays.pixel_step_y);
  const double scale = start_scale(rays, bounding_centre, state.bounding_radius, s.aperture_radius);
  const glm::dvec3 centre_dir = rays.first_pixel_dir +
                                rays.pixel_step_x * (0.5 * (rays.width_px - 1)) +
                                rays.pixel_step_y * (0.5 * (rays.height_px - 1));
  put_hi_lo(fc.ray_start, fc.ray_start_lo, rays.eye + centre_dir * scale);
  put_hi_lo(fc.start_step_x, fc.start_step_x_lo, rays.pixel_step_x * scale);
  put_hi_lo(fc.start_step_y, fc.start_step_y_lo, rays.pixel_step_y * scale);
  put_hi_lo(fc.start_scale, fc.start_scale_lo, scale);
  fc.ao_reference_steps = static_cast<float>(s.ao_reference_steps);
  fc.refine_steps = s.refine_steps;
  // Cone blocks on the whole image's grid (a window's offset into its first block is the phase);
  // a lattice's blocks are its own (its rays are not the whole image's neighbours).
  const bool band =
      s.window.full_width_px > 0 && s.window.stride_x_px <= 1 && s.window.stride_y_px <= 1;
  fc.cone_phase_x = band ? s.window.x0_px % FR_CONE_BLOCK : 0;
  fc.cone_phase_y = band ? s.window.y0_px % FR_CONE_BLOCK : 0;
  fc.cone_blocks_x = (s.width_px + fc.cone_phase_x + FR_CONE_BLOCK - 1) / FR_CONE_BLOCK;
  fc.cone_blocks_y = (s.height_px + fc.cone_phase_y + FR_CONE_BLOCK - 1) / FR_CONE_BLOCK;
  // The whole image's pixel grid (a window's origin and strides), for the random numbers.
  const bool windowed = s.window.full_width_px > 0;
  fc.pixel_origin_x = windowed ? s.window.x0_px : 0;
  fc.pixel_origin_y = windowed ? s.window.y0_px : 0;
  fc.pixel_stride_x = windowed ? std::max(1, s.window.stride_x_px) : 1;
  fc.pixel_stride_y = windowed ? std::max(1, s.window.stride_y_px) : 1;
  fc.full_width = rays.width_px;
  fc.full_height = rays.height_px;
  fc.seed = s.seed;
  fc.path_max_bounces = s.path_max_bounces;
  fc.transmission = s.transmission;
  fc.ior = s.ior;
  fc.absorption = static_cast<float>(s.absorption / state.bounding_radius);
  fc.emission = s.emission;
  fc.metalness = s.metalness;
  fc.specular_roughness = s.specular_roughness;
  fc.subsurface = s.subsurface;
  fc.mean_free_path = static_cast<float>(s.mean_free_path * state.bounding_radius);
  fc.aperture_blades = s.aperture_blades;
  put(fc.camera_right, rays.right);
  put(fc.camera_up, rays.up);
  put(fc.camera_forward, rays.forward);

  // Lights: the scene's (the loader refuses more than FR_MAX_SCENE_LIGHTS); without any, one from
  // above-behind the camera.
  int count = 0;
  for (const fr_light& l : state.lights) {
    if (count == FR_MAX_LIGHTS) break;
    // A light of no intensity lights nothing: left out, its shadow rays are never marched (an
    // imported scene's unused auxiliary lights, a light the user turned down).
    if (l.intensity == 0 || (l.color[0] == 0 && l.color[1] == 0 && l.color[2] == 0)) continue;
    const glm::dvec3 color = to_dvec3(l.color) * l.intensity;
    const bool point = l.kind == FR_LIGHT_POINT;
    put(fc.light_vector[count], to_dvec3(l.vector));
    put(fc.light_color[count], color);
    fc.light_kind[count] = point ? FR_KERNEL_LIGHT_POINT : FR_KERNEL_LIGHT_DIRECTIONAL;
    fc.light_attenuation[count] = static_cast<float>(point ? l.attenuation : 0);
    fc.light_falloff[count] = static_cast<float>(point ? l.falloff : 0);
    fc.light_radius[count] = static_cast<float>(l.radius);
    ++count;
  }
  if (state.lights.empty()) {
    put(fc.light_vector[0], -rays.forward - rays.up + 0.5 * rays.right);
    put(fc.light_color[0], glm::dvec3(1.2));
    fc.light_kind[0] = FR_KERNEL_LIGHT_DIRECTIONAL;
    count = 1;
  }
  fc.light_count = count;

  const double radius = state.bounding_radius;
  put(fc.ambient_color, s.ambient);
  put(fc.albedo, s.albedo);
  fc.reflectivity = s.reflectivity;
  put(fc.sky_zenith, s.sky_zenith);
  put(fc.sky_horizon, s.sky_horizon);
  put(fc.sky_up, rays.up);
  // The panorama's frame: its zenith the camera's (world) up vector, not the view's, so that the
  // sky stays put as the camera turns; its azimuth 0 towards world z (or x, if up is along z),
  // turned about the zenith by the rotation. Its size is the renderer's to fill in.
  {
    const glm::dvec3 up = glm::normalize(effective_up(state.camera));
    const glm::dvec3 ref = std::abs(up.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 z0 = glm::normalize(ref - up * glm::dot(ref, up));
    const glm::dvec3 x0 = glm::cross(up, z0);
    const double turn = s.environment_rotation_deg * std::numbers::pi / 180.0;
    put(fc.env_axes[0], std::cos(turn) * x0 + std::sin(turn) * z0);
    put(fc.env_axes[1], up);
    put(fc.env_axes[2], std::cos(turn) * z0 - std::sin(turn) * x0);
    fc.env_intensity = s.environment_intensity;
  }
  put(fc.glow_color, s.glow_color);
  fc.glow_strength = s.glow_strength;
  // The power-law fog is fog_scale * (t / R)^0.75 = (fog_scale / R^0.75) * t^0.75.
  put(fc.fog_color, s.fog_color);
  fc.fog_scale = static_cast<float>(s.fog_scale / std::pow(radius, 0.75));

  fc.width = s.width_px;  // this image's (a window's): the buffers' size
  fc.height = s.height_px;
  fc.max_steps = s.max_steps;
  fc.shadow_max_steps = s.shadow_max_steps;
  fc.bounce_max_steps = std::min(s.bounce_max_steps, s.max_steps);
  fc.bounce_shadow_max_steps = s.bounce_shadow_max_steps;
  fc.max_bounces = s.max_bounces;
  fc.ao_samples = std::max(1, s.ao_samples);
  fc.sample_index = sample_index;
  fc.pixel_angle_rad = static_cast<float>(rays.pixel_angle_rad);
  fc.hit_threshold_k = s.hit_threshold_k;
  fc.hit_threshold_abs = s.hit_threshold_abs;
  fc.bounding_radius = static_cast<float>(radius);
  fc.threshold_floor_scale =
      static_cast<float>(threshold_floor_scale(glm::length(rays.eye - bounding_centre), radius));
  fc.step_scale = s.step_scale;
  fc.ao_strength = s.ao_strength;
  fc.ao_distance = static_cast<float>(s.ao_distance * radius);
  fc.shadow_softness = s.shadow_softness;
  fc.specular_strength = s.specular_strength;
  fc.specular_power = s.specular_power;
  fc.roughness = s.roughness;
  fc.fresnel_f0 = s.fresnel_f0;
  fc.fog_density = static_cast<float>(s.fog_density / radius);
  fc.glow_falloff = static_cast<float>(s.glow_falloff * radius);
  fc.aperture_radius = s.aperture_radius;
  fc.focus_distance = static_cast<float>(
      s.focus_distance > 0
          ? s.focus_distance
          : glm::length(to_dvec3(state.camera.target) - to_dvec3(state.camera.eye)));
  const auto jitter = sample_jitter(sample_index);
  fc.jitter_x = static_cast<float>(jitter[0]);
  fc.jitter_y = static_cast<float>(jitter[1]);
  fc.accumulate_weight = 1.0f / static_cast<float>(sample_index + 1);
  fc.relaxation = s.relaxation;
  return fc;
}

}  // namespace fr
