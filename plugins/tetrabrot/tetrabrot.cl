/* tetrabrot.cl — the scene's DE: the library's Tetrabrot. */
#include "fr/hypercomplex.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_tetrabrot(p, PARAM(iterations), &trap);
}
