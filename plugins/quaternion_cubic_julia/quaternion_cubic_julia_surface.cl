/* quaternion_cubic_julia_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_quaternion_cubic_julia(p, PARAM(slice_w), PARAM(c), PARAM(c_w), to_real(4), PARAM(iterations),
                                   &trap);
  return surface_from_trap(trap, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
