/* menger.cl — the scene's DE: the library's folded Menger sponge. */
#include "fr/menger.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_menger(p, PARAM(iterations), PARAM(scale), PARAM(offset), PARAM(rotation_deg) * (scalar_t)(M_PI / 180), &trap);
}

#if FR_DD
/* The same at a point given in pairs, for views past double (render.precision "dd"). */
#include "fr/menger_dd.cl"

real_t scene_de_dd(dd3_t p, __constant const scene_params_t* params, real_t resolution) {
  return de_menger_dd(p, PARAM(iterations), PARAM(scale), PARAM(offset),
                      PARAM(rotation_deg) * (scalar_t)(M_PI / 180), resolution);
}
#endif
