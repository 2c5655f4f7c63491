/* bristorbrot_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_bristorbrot(p, to_real(16), PARAM(iterations), &trap);
  return surface_from_trap(trap, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
