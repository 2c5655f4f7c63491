/* mirror_hall_surface.cl — silvered walls and floor, a porcelain flake tinted by level. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t flake = hall_flake(p, params, &trap);
  const surface_t f = surface_from_trap(trap, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0.15);
  const real_t floor_d = hall_floor(p), walls = hall_walls(p);
  surface_t s;
  s.albedo = v3s(0.2, 0.2, 0.22);
  s.reflectivity = to_real(PARAM(mirror));
  real_t nearest = floor_d;
  {
    const mask_t here = walls < nearest;
    s.albedo = v3_select(here, v3s(0.25, 0.25, 0.27), s.albedo);
    s.reflectivity = lane_select(here, to_real(PARAM(mirror)), s.reflectivity);
    nearest = fmin(nearest, walls);
  }
  {
    const mask_t here = flake < nearest;
    s.albedo = v3_select(here, f.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0.15), s.reflectivity);
    nearest = fmin(nearest, flake);
  }
  return s;
}
