/* sphereflake.cl — the scene's DE: the library's sphereflake. */
#include "fr/recursive.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_sphereflake(p, PARAM(levels), PARAM(child_scale), &trap);
}
