/* pythagoras_tree_surface.cl — colour by orbit trap: the level of the nearest branch. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_pythagoras_tree(p, PARAM(levels), PARAM(child_scale), PARAM(tilt_deg) * (scalar_t)(M_PI / 180),
                            PARAM(width), &trap);
  return surface_from_trap(trap, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
