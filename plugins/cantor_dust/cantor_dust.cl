/* cantor_dust.cl — the scene's DE: the library's Cantor dust. */
#include "fr/cantor.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_cantor_dust(p, PARAM(iterations), PARAM(scale), &trap);
}
