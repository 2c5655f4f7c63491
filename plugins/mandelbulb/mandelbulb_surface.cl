/* mandelbulb_surface.cl — colour by orbit trap: how close each point's orbit came to the origin. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_mandelbulb(p, PARAM(power), to_real(PARAM(bailout)), PARAM(iterations), &trap);
  return surface_from_trap(trap, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0);
}
