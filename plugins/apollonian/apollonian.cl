/* apollonian.cl — the scene's DE: the library's Apollonian network. */
#include "fr/kleinian.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_apollonian(p, PARAM(iterations), PARAM(inversion_k), PARAM(extent), &trap);
}
