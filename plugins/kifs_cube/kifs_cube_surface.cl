/* kifs_cube_surface.cl — colour by orbit trap. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_kifs_octahedron(p, PARAM(iterations), PARAM(scale), PARAM(offset),
                            PARAM(angle_x_deg) * (scalar_t)(M_PI / 180), PARAM(angle_y_deg) * (scalar_t)(M_PI / 180),
      PARAM(angle_z_deg) * (scalar_t)(M_PI / 180), &trap);
  return surface_from_trap(trap / fmax(v3_length2(PARAM(offset)), to_real(1e-6)), PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0);
}
