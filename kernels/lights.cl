/* lights.cl — what one light delivers at a surface point: direction, distance and radiance.
 * Point lights fall off as k / (1 + a d^e) (fr_light in the ABI); directional lights do not. */

typedef struct light_sample_t {
  vec3_t to_light; /* unit */
  real_t distance; /* to the light; FR_SCALAR_MAX for a directional light */
  vec3_t radiance; /* linear RGB arriving at p */
} light_sample_t;

light_sample_t sample_light(int i, vec3_t p, __constant const fr_frame_constants* fc) {
  light_sample_t s;
  vec3_t v = v3_from_float4(fc->light_vector[i]);
  vec3_t color = v3_from_float4(fc->light_color[i]);
  if (fc->light_kind[i] == FR_KERNEL_LIGHT_DIRECTIONAL) {
    s.to_light = v3_normalize(v3_neg(v));
    s.distance = (real_t)FR_SCALAR_MAX; /* shadow rays end where they leave the bounds */
    s.radiance = color;
  } else {
    vec3_t d = v3_sub(v, p);
    s.distance = v3_length(d);
    s.to_light = v3_scale(d, (real_t)1 / fmax(s.distance, (real_t)FR_SCALAR_MIN));
    real_t a = (real_t)fc->light_attenuation[i];
    real_t falloff = a * pow_nonneg(s.distance, (real_t)fc->light_falloff[i]);
    s.radiance = v3_scale(color, (real_t)1 / ((real_t)1 + falloff));
  }
  return s;
}
