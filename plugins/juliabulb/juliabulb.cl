/* juliabulb.cl — the scene's DE: the library's Juliabulb (the Mandelbulb's Julia set). */
#include "fr/mandelbulb.cl"

/* Near its poles the escape-time estimate runs long: `fractalis check`'s de-near-surface found
 * 2.2% of its points over 1.1x their distance at the default c, still 1.1% at 0.7 of it; 0.55 of
 * it keeps the march on the near side (0.4%). */
real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return to_real(0.55) * de_juliabulb(p, PARAM(power), PARAM(c), to_real(PARAM(bailout)),
                                     PARAM(iterations), &trap);
}
