/* menger_4d.cl — the scene's DE: the library's 4D Menger sponge, sliced. */
#include "fr/menger.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_menger_4d(p, PARAM(slice_w), PARAM(iterations), PARAM(scale), &trap);
}
