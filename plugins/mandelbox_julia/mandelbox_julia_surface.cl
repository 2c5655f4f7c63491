/* mandelbox_julia_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_mandelbox_julia(p, PARAM(iterations), PARAM(scale), PARAM(min_radius), PARAM(fixed_radius),
                            PARAM(fold_limit), PARAM(c), &trap);
  return surface_from_trap(trap / 4, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
