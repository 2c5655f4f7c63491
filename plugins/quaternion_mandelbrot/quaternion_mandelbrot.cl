/* quaternion_mandelbrot.cl — the scene's DE: the library's quaternion Mandelbrot set, sliced. */
#include "fr/julia.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_quaternion_mandelbrot(p, PARAM(slice_w), to_real(PARAM(bailout)), PARAM(iterations),
                                  &trap);
}
