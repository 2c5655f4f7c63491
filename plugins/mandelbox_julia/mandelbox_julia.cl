/* mandelbox_julia.cl — the scene's DE: the library's Mandelbox Julia set. */
#include "fr/mandelbox.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_mandelbox_julia(p, PARAM(iterations), PARAM(scale), PARAM(min_radius), PARAM(fixed_radius),
                            PARAM(fold_limit), PARAM(c), &trap);
}

#if FR_DD
/* The same at a point given in pairs, for views past double (render.precision "dd"). */
#include "fr/mandelbox_dd.cl"

real_t scene_de_dd(dd3_t p, __constant const scene_params_t* params, real_t resolution) {
  return de_mandelbox_julia_dd(p, PARAM(iterations), PARAM(scale), PARAM(min_radius),
                               PARAM(fixed_radius), PARAM(fold_limit), PARAM(c), resolution);
}
#endif
