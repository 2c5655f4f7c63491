/* pseudo_kleinian_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_pseudo_kleinian(p, PARAM(iterations), PARAM(box_size), PARAM(inversion_k), PARAM(offset),
                            PARAM(tube_radius), PARAM(extent), &trap);
  return surface_from_trap(trap / 2, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
