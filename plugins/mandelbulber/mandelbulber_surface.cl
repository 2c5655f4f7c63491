/* mandelbulber_surface.cl — colour by orbit trap (Mandelbulber2's palettes are not imported). */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  mb2_de(p, params, &trap);
  return surface_from_trap(trap / 4, PARAM(color_near), PARAM(color_far), PARAM(color_contrast),
                           0);
}
