/* jerusalem_cube.cl — the scene's DE: the library's Jerusalem cube. */
#include "fr/jerusalem.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_jerusalem_cube(p, PARAM(iterations), &trap);
}
