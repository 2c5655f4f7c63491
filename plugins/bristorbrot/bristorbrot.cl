/* bristorbrot.cl — the scene's DE: the library's Bristorbrot. */
#include "fr/mandelbulb.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_bristorbrot(p, to_real(16), PARAM(iterations), &trap);
}
