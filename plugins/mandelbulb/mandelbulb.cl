/* mandelbulb.cl — the scene's DE: the library's power-n Mandelbulb with this scene's parameters. */
#include "fr/mandelbulb.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_mandelbulb(p, PARAM(power), to_real(PARAM(bailout)), PARAM(iterations), &trap);
}

#if FR_DD
/* The same at a point given in pairs, for views past double (render.precision "dd"): whole
 * powers only (a fractional one runs in double there; fr/mandelbulb_dd.cl). */
#include "fr/mandelbulb_dd.cl"

real_t scene_de_dd(dd3_t p, __constant const scene_params_t* params, real_t resolution) {
  return de_mandelbulb_dd(p, PARAM(power), to_real(PARAM(bailout)), PARAM(iterations), resolution);
}
#endif
