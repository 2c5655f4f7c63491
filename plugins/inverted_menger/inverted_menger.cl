/* inverted_menger.cl — the scene's DE: the library's Menger sponge, inverted in a sphere. */
#include "fr/menger.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const vec3_t q = p_invert_sphere(p, v3s(0, 0, 0), PARAM(radius2));
  return op_invert_de(de_menger(q, PARAM(iterations), 3, v3s(1, 1, 1), 0, &trap), v3_length(p),
                      PARAM(radius2));
}
