/* ao.cl — ambient occlusion from the march's own step count: rays that needed many steps passed
 * close to a lot of surface. Free, since the march counts steps anyway. Result in [0, 1]. */

inline real_t step_count_ao(real_t steps, __constant const fr_frame_constants* fc) {
  real_t openness = clamp((real_t)1 - steps / (real_t)fc->max_steps, (real_t)0, (real_t)1);
  return pow_nonneg(openness, (real_t)fc->ao_strength);
}

/* The renderer's hook (render.cl). */
#define FR_APPLY_AO(ao, m) ao = step_count_ao((m).steps, fc)
