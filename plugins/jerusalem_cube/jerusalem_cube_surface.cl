/* jerusalem_cube_surface.cl — colour by how many of the levels took an edge cube. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_jerusalem_cube(p, PARAM(iterations), &trap);
  return surface_from_trap(trap * trap, PARAM(color_near), PARAM(color_far), 1, 0);
}
