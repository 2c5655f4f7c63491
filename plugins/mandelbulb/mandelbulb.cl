/* mandelbulb.cl — the scene's DE: the library's power-n Mandelbulb with this scene's parameters. */
#include "fr/mandelbulb.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_mandelbulb(p, PARAM(power), to_real(PARAM(bailout)), PARAM(iterations), &trap);
}
