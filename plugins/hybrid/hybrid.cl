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

/* The chain's six steps, in order, each by `apply` (in double, or in pairs below). */
#define HYBRID_STEPS(apply) apply(1) apply(2) apply(3) apply(4) apply(5) apply(6)

inline real_t hybrid_de(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t r2 = v3_length2(z);
  real_t orbit_min = r2;
  const real_t bailout2 = to_real(PARAM(bailout) * PARAM(bailout));
  for (int i = 0; i < PARAM(iterations); ++i) {
    const mask_t live = r2 < bailout2;
    if (!any_lane(live)) break;
    HYBRID_STEPS(HYBRID_APPLY)
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

#if FR_DD
/* The same at a point given in pairs, for views past double (render.precision "dd"): the steps
 * in pairs while dr x resolution is below 1000 ulps of the orbit's size, in double after, as
 * fr/hybrid_dd.cl explains; a lane whose dr fell back below that bound is evaluated again with
 * every iteration in pairs. */
#include "fr/hybrid_dd.cl"

#define HYBRID_APPLY_DD(n)                                                                     \
  for (int k = 0; k < PARAM(step##n##_repeat); ++k)                                            \
    hybrid_step_dd(PARAM(step##n), live, &z, &dr, p, PARAM(step##n##_a), PARAM(step##n##_b), \
                   PARAM(step##n##_v));

/* The size of the offsets the steps add (a rotation's v is its angles, not an offset). */
#define HYBRID_OFFSET_SIZE(n)                                                       \
  (PARAM(step##n) == HYBRID_NONE || PARAM(step##n) == HYBRID_ROTATE ? to_real(0) \
                                                                     : v3_length(PARAM(step##n##_v)))

inline real_t hybrid_de_dd_once(dd3_t p, __constant const scene_params_t* params,
                                real_t resolution, mask_t* short_of) {
  const real_t switch_ulps = to_real(1000 * DBL_EPSILON);
  const real_t bailout2 = to_real(PARAM(bailout) * PARAM(bailout));
  const real_t p_size = sqrt(v3_length2(dd3_to_v3(p)));
  const real_t offsets =
      fmax(fmax(fmax(HYBRID_OFFSET_SIZE(1), HYBRID_OFFSET_SIZE(2)), HYBRID_OFFSET_SIZE(3)),
           fmax(fmax(HYBRID_OFFSET_SIZE(4), HYBRID_OFFSET_SIZE(5)), HYBRID_OFFSET_SIZE(6)));
  const real_t floor_size = fmax(p_size, offsets);
  dd3_t z = p;
  real_t dr = to_real(1);
  real_t r2 = p_size * p_size;
  int i = 0;
  for (; i < PARAM(iterations); ++i) {
    const mask_t live = r2 < bailout2;
    if (!any_lane(live)) break;
    const mask_t needs_pairs = fabs(dr) * resolution <= switch_ulps * fmax(sqrt(r2), floor_size);
    if (!any_lane(live & needs_pairs)) break; /* the rest in double, below */
    HYBRID_STEPS(HYBRID_APPLY_DD)
    r2 = lane_select(live, v3_length2(dd3_to_v3(z)), r2);
  }
  /* (i is the same in every lane: a scalar condition picks the whole mask.) */
  const mask_t ended_in_pairs = i >= PARAM(iterations) ? FR_MASK_TRUE : (r2 >= bailout2);
  const real_t from_pairs = hybrid_estimate_dd(PARAM(estimate), z, dr);
  /* The rest in double, at p rounded (an ulp of |p| over dr: below the bound); the block's z and
   * p shadow the pairs, for HYBRID_APPLY. */
  const dd3_t z_pairs = z, p_pairs = p;
  *short_of = FR_MASK_FALSE;
  {
    vec3_t z = dd3_to_v3(z_pairs);
    const vec3_t p = dd3_to_v3(p_pairs);
    for (; i < PARAM(iterations); ++i) {
      const mask_t live = r2 < bailout2;
      if (!any_lane(live)) break;
      *short_of |= live & (fabs(dr) * resolution <= switch_ulps * fmax(sqrt(r2), floor_size));
      HYBRID_STEPS(HYBRID_APPLY)
      r2 = lane_select(live, v3_length2(z), r2);
    }
    return to_real(PARAM(de_factor)) *
           lane_select(ended_in_pairs, from_pairs, hybrid_estimate(PARAM(estimate), z, dr));
  }
}

real_t scene_de_dd(dd3_t p, __constant const scene_params_t* params, real_t resolution) {
  mask_t short_of;
  real_t d = hybrid_de_dd_once(p, params, resolution, &short_of);
  if (any_lane(short_of)) {
    mask_t unused;
    d = lane_select(short_of, hybrid_de_dd_once(p, params, to_real(0), &unused), d);
  }
  return d;
}
#endif
