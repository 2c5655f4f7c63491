/* sierpinski.cl — the scene's DE: the library's folded Sierpinski tetrahedron. */
#include "fr/sierpinski.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_sierpinski(p, PARAM(iterations), PARAM(scale), PARAM(offset), &trap);
}
