/* mandelbox_julia.cl — the scene's DE: the library's Mandelbox Julia set. */
#include "fr/mandelbox.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_mandelbox_julia(p, PARAM(iterations), PARAM(scale), PARAM(min_radius), PARAM(fixed_radius),
                            PARAM(fold_limit), PARAM(c), &trap);
}
