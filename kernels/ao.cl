/* ao.cl — ambient occlusion, in [0, 1] (1: open). FR_AO picks:
 *   FR_AO_STEP_COUNT  step count: rays that needed many march steps passed close to a lot of
 *      surface. Free, since the march counts steps anyway; ao_reference_steps steps is full occlusion. The
 *      count stops once the ray is within a pixel footprint of the surface (march.cl), so a
 *      finer hit threshold does not darken the picture.
 *   FR_AO_SAMPLED  sampled: ao_samples DE evaluations along the normal up to ao_distance; where the DE is
 *      smaller than the distance from the surface, something is near (nearer samples weigh
 *      more). */

#if FR_AO == FR_AO_SAMPLED
real_t sampled_ao(vec3_t p, vec3_t n, __constant const fr_frame_constants* fc,
                  __constant const scene_params_t* params) {
  real_t occlusion = (real_t)0;
  real_t weight = (real_t)1;
  for (int i = 1; i <= fc->ao_samples; ++i) {
    real_t h = (real_t)(fc->ao_distance * i / fc->ao_samples);
    real_t d = scene_de(v3_mad(p, n, h), params);
    occlusion += weight * fmax(h - d, (real_t)0) / h;
    weight *= (real_t)0.5;
  }
  return clamp((real_t)1 - (real_t)fc->ao_strength * (real_t)0.5 * occlusion, (real_t)0, (real_t)1);
}
#define FR_APPLY_AO(ao, p, n, m) ao = sampled_ao(p, n, fc, params)
#define FR_AO_EVALS (fc->ao_samples)
#else
/* Normalised by a fixed step count, not the step budget: raising max_steps must not change
 * converged pixels. */
inline real_t step_count_ao(real_t steps, __constant const fr_frame_constants* fc) {
  real_t openness =
      clamp((real_t)1 - steps / (real_t)fc->ao_reference_steps, (real_t)0, (real_t)1);
  return pow_nonneg(openness, (real_t)fc->ao_strength);
}
#define FR_APPLY_AO(ao, p, n, m) ao = step_count_ao((m).ao_steps, fc)
#endif
