/* inverted_menger_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const vec3_t q = p_invert_sphere(p, v3s(0, 0, 0), PARAM(radius2));
  op_invert_de(de_menger(q, PARAM(iterations), 3, v3s(1, 1, 1), 0, &trap), v3_length(p),
                      PARAM(radius2));
  return surface_from_trap(trap / 3, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
