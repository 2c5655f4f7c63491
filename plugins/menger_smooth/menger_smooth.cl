/* menger_smooth.cl — the scene's DE: the library's smooth Menger sponge. */
#include "fr/menger.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_menger_smooth(p, PARAM(iterations), PARAM(scale), PARAM(offset), PARAM(smoothness), &trap);
}
