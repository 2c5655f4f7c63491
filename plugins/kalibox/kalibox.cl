/* kalibox.cl — the scene's DE: the library's Kalibox. */
#include "fr/kali.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_kalibox(p, PARAM(iterations), PARAM(scale), PARAM(min_radius2), PARAM(translation), PARAM(c),
                    PARAM(angle_x_deg) * (scalar_t)(M_PI / 180), PARAM(angle_y_deg) * (scalar_t)(M_PI / 180),
      PARAM(angle_z_deg) * (scalar_t)(M_PI / 180), &trap);
}
