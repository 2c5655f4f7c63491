/* inverted_sierpinski_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const vec3_t q = p_invert_sphere(p, v3s(0, 0, 0), PARAM(radius2));
  op_invert_de(de_sierpinski(q, PARAM(iterations), 2, v3s(1, 1, 1), &trap), v3_length(p),
                      PARAM(radius2));
  return surface_from_trap(trap / 3, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
