/* menger_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_menger(p, PARAM(iterations), PARAM(scale), PARAM(offset), PARAM(rotation_deg) * (scalar_t)(M_PI / 180), &trap);
  /* The trap grows with the scale^iterations blow-up; compare its logarithm. */
  real_t t = log(fmax(trap, to_real(1))) / to_real(PARAM(iterations) * 2.2 + 1);
  return surface_from_trap(t, PARAM(color_near), PARAM(color_far), 3, 0);
}
