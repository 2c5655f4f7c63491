/* burning_bulb.cl — the scene's DE: the library's burning bulb. */
#include "fr/mandelbulb.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_burning_bulb(p, PARAM(power), to_real(2), PARAM(iterations), &trap);
}
