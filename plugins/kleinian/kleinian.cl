/* kleinian.cl — the scene's DE: the library's Kleinian limit set. */
#include "fr/kleinian.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_kleinian(p, PARAM(iterations), PARAM(trace_re), PARAM(trace_im), PARAM(box_x), PARAM(box_z),
                     PARAM(extent), &trap);
}
