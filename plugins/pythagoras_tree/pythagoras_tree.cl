/* pythagoras_tree.cl — the scene's DE: the library's Pythagoras tree. */
#include "fr/recursive.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_pythagoras_tree(p, PARAM(levels), PARAM(child_scale), PARAM(tilt_deg) * (scalar_t)(M_PI / 180),
                            PARAM(width), &trap);
}
