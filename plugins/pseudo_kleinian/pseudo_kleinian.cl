/* pseudo_kleinian.cl — the scene's DE: the library's pseudo-Kleinian. */
#include "fr/kleinian.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_pseudo_kleinian(p, PARAM(iterations), PARAM(box_size), PARAM(inversion_k), PARAM(offset),
                            PARAM(tube_radius), PARAM(extent), &trap);
}
