/* quaternion_cubic_julia.cl — the scene's DE: the library's cubic quaternion Julia set. */
#include "fr/hypercomplex.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_quaternion_cubic_julia(p, PARAM(slice_w), PARAM(c), PARAM(c_w), to_real(4), PARAM(iterations),
                                   &trap);
}
