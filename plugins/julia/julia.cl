/* julia.cl — the scene's DE: the library's quaternion Julia set, sliced at w. */
#include "fr/julia.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_julia_quaternion(p, PARAM(slice_w), PARAM(c), PARAM(c_w), to_real(PARAM(bailout)),
                             PARAM(iterations), &trap);
}
