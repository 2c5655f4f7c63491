/* menger_temple_surface.cl — pale stone for the sponges, darker for the plinth, a dusty floor;
 * the nearest shape at p decides. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t floor_d = sd_floor_disc(p, -1.5, 6.5, 0.5);
  const real_t plinth = temple_plinth(p);
  const real_t pillars = temple_pillars(p, params, &trap);
  const real_t sponge = temple_sponge(p, params, &trap);
  const surface_t stone = surface_from_trap(trap / 3, PARAM(stone_color), PARAM(stone_shade), 1, 0);
  surface_t s;
  s.albedo = PARAM(floor_color);
  s.reflectivity = to_real(0);
  real_t nearest = floor_d;
  {
    const mask_t here = plinth < nearest;
    s.albedo = v3_select(here, v3_scale(PARAM(stone_shade), to_real(0.8)), s.albedo);
    s.reflectivity = lane_select(here, to_real(0), s.reflectivity);
    nearest = fmin(nearest, plinth);
  }
  {
    const mask_t here = pillars < nearest;
    s.albedo = v3_select(here, PARAM(stone_color), s.albedo);
    s.reflectivity = lane_select(here, to_real(0), s.reflectivity);
    nearest = fmin(nearest, pillars);
  }
  {
    const mask_t here = sponge < nearest;
    s.albedo = v3_select(here, stone.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0), s.reflectivity);
    nearest = fmin(nearest, sponge);
  }
  return s;
}
