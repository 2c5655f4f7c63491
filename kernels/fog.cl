/* fog.cl — distance fog over a surface at path length t. FR_FOG picks:
 *   FR_FOG_POWER        a power law: amount = fog_scale * t^0.75, clamped to 1
 *   FR_FOG_EXPONENTIAL  exponential: amount = 1 - exp(-density * t)
 * Neither divides by a ray component, so a horizontal ray cannot produce NaN. */

inline real_t fog_amount(real_t t, __constant const fr_frame_constants* fc) {
#if FR_FOG == FR_FOG_EXPONENTIAL
  return (real_t)1 - exp(-(real_t)fc->fog_density * t);
#else
  return fmin((real_t)fc->fog_scale * pow_nonneg(t, (real_t)0.75), (real_t)1);
#endif
}

#define FR_APPLY_FOG(color, t)                                                          \
  do {                                                                                  \
    real_t fog_ = fog_amount(t, fc);                                                    \
    color = v3_mad(v3_scale(color, (real_t)1 - fog_), v3_from_float4(fc->fog_color), fog_); \
  } while (0)
