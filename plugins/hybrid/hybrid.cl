/* hybrid.cl — the composer's DE: the chosen steps of fr/hybrid.cl, in order, each iteration. */
#include "fr/hybrid.cl"

/* hybrid.c lists the kinds by name in HYBRID_* order; the kernel gets each name's index. */
#if FR_CHOICE_step1_bulb != HYBRID_BULB || FR_CHOICE_step1_menger != HYBRID_MENGER || \
    FR_CHOICE_step1_rotate != HYBRID_ROTATE || FR_CHOICE_step1_abs_fold != HYBRID_ABS_FOLD || \
    FR_CHOICE_estimate_box != HYBRID_ESTIMATE_BOX
#error "hybrid.c's kinds are out of step with fr/hybrid.cl"
#endif

#define HYBRID_APPLY(n)                                                                      \
  for (int k = 0; k < PARAM(step##n##_repeat); ++k)                                          \
    hybrid_step(PARAM(step##n), live, &z, &dr, p, PARAM(step##n##_a), PARAM(step##n##_b), \
                PARAM(step##n##_v));

inline real_t hybrid_de(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t r2 = v3_length2(z);
  real_t orbit_min = r2;
  const real_t bailout2 = to_real(PARAM(bailout) * PARAM(bailout));
  for (int i = 0; i < PARAM(iterations); ++i) {
    const mask_t live = r2 < bailout2;
    if (!any_lane(live)) break;
    HYBRID_APPLY(1)
    HYBRID_APPLY(2)
    HYBRID_APPLY(3)
    HYBRID_APPLY(4)
    HYBRID_APPLY(5)
    HYBRID_APPLY(6)
    r2 = lane_select(live, v3_length2(z), r2);
    orbit_min = lane_select(live, fmin(orbit_min, r2), orbit_min);
  }
  *trap = orbit_min;
  return to_real(PARAM(de_factor)) * hybrid_estimate(PARAM(estimate), z, dr);
}

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return hybrid_de(p, params, &trap);
}
