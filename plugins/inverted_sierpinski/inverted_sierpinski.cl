/* inverted_sierpinski.cl — the scene's DE: the library's Sierpinski tetrahedron, inverted in a sphere. */
#include "fr/operators.cl"
#include "fr/sierpinski.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const vec3_t q = p_invert_sphere(p, v3s(0, 0, 0), PARAM(radius2));
  return op_invert_de(de_sierpinski(q, PARAM(iterations), 2, v3s(1, 1, 1), &trap), v3_length(p),
                      PARAM(radius2));
}
