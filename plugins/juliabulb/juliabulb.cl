/* juliabulb.cl — the scene's DE: the library's Juliabulb (the Mandelbulb's Julia set). */
#include "fr/mandelbulb.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_juliabulb(p, PARAM(power), PARAM(c), to_real(PARAM(bailout)), PARAM(iterations),
                      &trap);
}
