/* sierpinski_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_sierpinski(p, PARAM(iterations), PARAM(scale), PARAM(offset), &trap);
  real_t t = log(fmax(trap, to_real(1))) / to_real(PARAM(iterations) * 1.4 + 1);
  return surface_from_trap(t, PARAM(color_near), PARAM(color_far), 1, 0);
}
