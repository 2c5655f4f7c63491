/* fractal_city_surface.cl — concrete towers shaded by orbit trap, dark streets. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t towers = city_towers(p, params, &trap);
  const surface_t t = surface_from_trap(trap / 3, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0);
  const real_t ground = city_ground(p);
  surface_t s;
  s.albedo = v3s(0.16, 0.16, 0.18);
  s.reflectivity = to_real(0.15);
  real_t nearest = ground;
  {
    const mask_t here = towers < nearest;
    s.albedo = v3_select(here, t.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0), s.reflectivity);
    nearest = fmin(nearest, towers);
  }
  return s;
}
