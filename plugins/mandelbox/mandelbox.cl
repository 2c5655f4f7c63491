/* mandelbox.cl — the scene's DE: the library's Mandelbox (Tom Lowe's Amazing Box). */
#include "fr/mandelbox.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_mandelbox(p, PARAM(iterations), PARAM(scale), PARAM(min_radius), PARAM(fixed_radius),
                      PARAM(fold_limit), &trap);
}

#if FR_DD
/* The same at a point given in pairs, for views past double (render.precision "dd"). */
#include "fr/mandelbox_dd.cl"

real_t scene_de_dd(dd3_t p, __constant const scene_params_t* params, real_t resolution) {
  return de_mandelbox_dd(p, PARAM(iterations), PARAM(scale), PARAM(min_radius),
                         PARAM(fixed_radius), PARAM(fold_limit), resolution);
}
#endif
