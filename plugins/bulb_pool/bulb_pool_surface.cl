/* bulb_pool_surface.cl — orbit-trap colours on the bulb, mirror water, a stone rim and grass. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t bulb = pool_bulb(p, params, &trap);
  const surface_t bulb_s = surface_from_trap(trap, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0);
  const real_t ground = pool_ground(p), water = pool_water(p), rim = pool_rim(p);
  surface_t s;
  s.albedo = v3s(0.32, 0.42, 0.25);
  s.reflectivity = to_real(0);
  real_t nearest = ground;
  {
    const mask_t here = water < nearest;
    s.albedo = v3_select(here, v3s(0.05, 0.09, 0.12), s.albedo);
    s.reflectivity = lane_select(here, to_real(PARAM(water_reflectivity)), s.reflectivity);
    nearest = fmin(nearest, water);
  }
  {
    const mask_t here = rim < nearest;
    s.albedo = v3_select(here, v3s(0.62, 0.6, 0.56), s.albedo);
    s.reflectivity = lane_select(here, to_real(0.05), s.reflectivity);
    nearest = fmin(nearest, rim);
  }
  {
    const mask_t here = bulb < nearest;
    s.albedo = v3_select(here, bulb_s.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0), s.reflectivity);
    nearest = fmin(nearest, bulb);
  }
  return s;
}
