/* menger_4d_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_menger_4d(p, PARAM(slice_w), PARAM(iterations), PARAM(scale), &trap);
  return surface_from_trap(trap / 4, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
