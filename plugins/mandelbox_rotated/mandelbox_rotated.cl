/* mandelbox_rotated.cl — the scene's DE: the library's rotated Mandelbox. */
#include "fr/mandelbox.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return de_mandelbox_rotated(p, PARAM(iterations), PARAM(scale), PARAM(min_radius), PARAM(fixed_radius),
                              PARAM(fold_limit), PARAM(angle_x_deg) * (scalar_t)(M_PI / 180), PARAM(angle_y_deg) * (scalar_t)(M_PI / 180),
      PARAM(angle_z_deg) * (scalar_t)(M_PI / 180), &trap);
}

#if FR_DD
/* The same at a point given in pairs, for views past double (render.precision "dd"). */
#include "fr/mandelbox_dd.cl"

real_t scene_de_dd(dd3_t p, __constant const scene_params_t* params, real_t resolution) {
  return de_mandelbox_rotated_dd(p, PARAM(iterations), PARAM(scale), PARAM(min_radius),
                                 PARAM(fixed_radius), PARAM(fold_limit),
                                 PARAM(angle_x_deg) * (scalar_t)(M_PI / 180),
                                 PARAM(angle_y_deg) * (scalar_t)(M_PI / 180),
                                 PARAM(angle_z_deg) * (scalar_t)(M_PI / 180), resolution);
}
#endif
