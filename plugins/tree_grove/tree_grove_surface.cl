/* tree_grove_surface.cl — bark to leaves by the branch's level, grass below. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t trees = grove_trees(p, params, &trap);
  const surface_t t = surface_from_trap(trap, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0);
  const real_t ground = grove_ground(p);
  surface_t s;
  s.albedo = v3s(0.3, 0.45, 0.2);
  s.reflectivity = to_real(0);
  real_t nearest = ground;
  {
    const mask_t here = trees < nearest;
    s.albedo = v3_select(here, t.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0), s.reflectivity);
    nearest = fmin(nearest, trees);
  }
  return s;
}
