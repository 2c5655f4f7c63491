/* shadow.cl — how much of each light reaches a surface point: march from just off the surface
 * towards the light (up to the light's distance, and out of the bounding sphere). FR_SHADOW picks:
 *   FR_SHADOW_HARD  hard: 0 as soon as the ray reaches the surface, else 1
 *   FR_SHADOW_SOFT  soft: the penumbra estimate, the smallest k * d / t along the ray (k = shadow_softness)
 * The result is clamped to [0, 1]: 1 is fully lit.
 *
 * One stream for all the lights: each lane marches its own point's shadow rays one after another
 * (the lights it faces, in order), starting the next as soon as one ends, so the packet runs
 * until the lane with the most shadow work is done — not, light after light, until the slowest
 * lane for that light is. Every ray takes exactly the steps it took when the lights went one at a
 * time (its own t, lit and step count), so the factors are the same. */

void shadow_factors(vec3_t p, vec3_t n, real_t h, const light_sample_t* lights,
                    const mask_t* facing, int light_count, int max_steps, real_t* shadow,
                    __constant const fr_frame_constants* fc,
                    __constant const scene_params_t* params FR_COUNTS_PARAM) {
  /* Start just off the surface, along the normal. */
  ray_t ray;
  ray.origin = v3_mad(p, n, 2 * h);
  const real_t t_start = 4 * h;
  real_t t_exit[FR_MAX_LIGHTS];
  for (int l = 0; l < light_count; ++l) {
    ray.dir = lights[l].to_light;
    real_t t_enter;
    intersect_bounds(ray, fc, &t_enter, &t_exit[l]);
    t_exit[l] = fmin(t_exit[l], lights[l].distance);
    shadow[l] = (real_t)1;
  }
  /* No steps: fully lit (a bounce's budget of 0, frame_constants.h). */
  if (max_steps <= 0) return;
  /* Per lane: the light of the ray it marches (or last marched; -1 before the first). */
  real_t light = (real_t)-1, t = (real_t)0, lit = (real_t)1, steps = (real_t)0, exit = (real_t)0;
  /* Hard shadows: the DE at the ray's first point (its clearance where it leaves the surface). */
  real_t first = (real_t)0;
  mask_t active = FR_MASK_FALSE, more = FR_MASK_TRUE;
  const int most = light_count * (max_steps + 1);
  for (int i = 0; i < most; ++i) {
    /* Lanes between rays take their next light (a ray that starts at its end is lit at once). */
    while (any_lane((!active) & more)) {
      const mask_t idle = (!active) & more;
      real_t next = (real_t)FR_MAX_LIGHTS;
      for (int l = light_count - 1; l >= 0; --l)
        next = lane_select(idle & facing[l] & ((real_t)l > light), (real_t)l, next);
      const mask_t starts = idle & (next < (real_t)FR_MAX_LIGHTS);
      more &= !(idle & !starts);
      light = lane_select(starts, next, light);
      for (int l = 0; l < light_count; ++l) {
        const mask_t mine = starts & (light == (real_t)l);
        ray.dir = v3_select(mine, lights[l].to_light, ray.dir);
        exit = lane_select(mine, t_exit[l], exit);
      }
      t = lane_select(starts, t_start, t);
      lit = lane_select(starts, 1, lit);
      steps = lane_select(starts, 0, steps);
      active |= starts & (t < exit);
    }
    if (!any_lane(active)) break;
    const real_t dist = scene_de(v3_mad(ray.origin, ray.dir, t), params);
    /* A lane that has no shadow ray at all idles on the first light's account. */
    for (int l = 0; l < light_count; ++l)
      FR_COUNT_LANES(FR_COUNT_SHADOW + l, active & (light == (real_t)l),
                     (light == (real_t)l) | (l == 0 ? light < (real_t)0 : FR_MASK_FALSE));
#if FR_SHADOW == FR_SHADOW_SOFT
    lit = lane_select(active, fmin(lit, (real_t)fc->shadow_softness * dist / t), lit);
#else
    /* Blocked where the DE falls below half the start's offset, or below half what it was at the
     * ray's first point when that is less (the clearance it left the surface with): a DE that under-estimates (half the distance, say)
     * starts a ray that grazes a convex surface below any fixed threshold, and such rays, lit
     * for the bounces that escape along them, came out dark for next-event estimation (a white
     * ball under a uniform panorama lost 1.7% of its light, tests/environment_test.cpp). A ray
     * that starts inside (a DE of 0 or less) is blocked. */
    first = lane_select(active & (steps == (real_t)0), dist, first);
    const real_t blocked_below = fmin(t_start * (real_t)0.5, (real_t)0.5 * first);
    lit = lane_select(active & ((dist < blocked_below) | (first <= (real_t)0)), 0, lit);
#endif
    steps += mask_to_real(active);
    mask_t going = active & (lit > (real_t)0.001) & (dist > (real_t)0);
    t = lane_select(going, t + fmax(dist, t_start * (real_t)0.5), t);
    going &= (t < exit) & (steps < (real_t)max_steps);
    /* Rays that ended: their light's factor. */
    const mask_t ended = active & !going;
    for (int l = 0; l < light_count; ++l)
      shadow[l] = lane_select(ended & (light == (real_t)l), clamp(lit, (real_t)0, (real_t)1),
                              shadow[l]);
    active = going;
  }
}

/* The renderer's hook (shade.cl). */
#define FR_APPLY_SHADOWS(shadow, p, n, h, lights, facing, count, max_steps) \
  shadow_factors(p, n, h, lights, facing, count, max_steps, shadow, fc, params FR_COUNTS_ARG)
