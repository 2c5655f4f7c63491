/* crystal_garden_surface.cl — orbit-trap colours on the crystals, sand below. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t crystals = garden_crystals(p, params, &trap);
  const surface_t c = surface_from_trap(trap / 2, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0.1);
  const real_t ground = garden_ground(p);
  surface_t s;
  s.albedo = v3s(0.72, 0.66, 0.55);
  s.reflectivity = to_real(0);
  real_t nearest = ground;
  {
    const mask_t here = crystals < nearest;
    s.albedo = v3_select(here, c.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0.1), s.reflectivity);
    nearest = fmin(nearest, crystals);
  }
  return s;
}
