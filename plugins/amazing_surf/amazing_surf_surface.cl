/* amazing_surf_surface.cl — colour by orbit trap: how close the orbit came to the origin. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_amazing_surf(p, PARAM(iterations), PARAM(scale), PARAM(min_radius), PARAM(fixed_radius),
               PARAM(fold_limit), &trap);
  return surface_from_trap(trap / to_real(4 * PARAM(fixed_radius) * PARAM(fixed_radius)), PARAM(color_near),
                           PARAM(color_far), PARAM(color_contrast), 0);
}
