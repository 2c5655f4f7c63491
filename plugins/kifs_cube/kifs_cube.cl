/* kifs_cube.cl — the scene's DE: the library's octahedral KIFS, about a cube corner. */
#include "fr/kifs.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_kifs_octahedron(p, PARAM(iterations), PARAM(scale), PARAM(offset),
                            PARAM(angle_x_deg) * (scalar_t)(M_PI / 180), PARAM(angle_y_deg) * (scalar_t)(M_PI / 180),
      PARAM(angle_z_deg) * (scalar_t)(M_PI / 180), &trap);
}
