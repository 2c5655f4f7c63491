/* shadow.cl — how much of a light reaches a surface point: march from just off the surface
 * towards the light (up to the light's distance, and out of the bounding sphere). FR_SHADOW picks:
 *   FR_SHADOW_HARD  hard: 0 as soon as the ray reaches the surface, else 1
 *   FR_SHADOW_SOFT  soft: the penumbra estimate, the smallest k * d / t along the ray (k = shadow_softness)
 * The result is clamped to [0, 1]: 1 is fully lit. */

real_t shadow_factor(vec3_t origin, vec3_t to_light, real_t t_start, real_t light_distance,
                     __constant const fr_frame_constants* fc,
                     __constant const scene_params_t* params, mask_t lanes,
                     int light_index FR_COUNTS_PARAM) {
  ray_t ray;
  ray.origin = origin;
  ray.dir = to_light;
  real_t t_enter, t_exit;
  intersect_bounds(ray, fc->bounding_radius, &t_enter, &t_exit);
  t_exit = fmin(t_exit, light_distance);
  real_t t = t_start;
  real_t lit = (real_t)1;
  mask_t active = lanes & (t < t_exit);
  for (int i = 0; i < fc->shadow_max_steps && any_lane(active); ++i) {
    vec3_t p = v3_mad(origin, to_light, t);
    real_t dist = scene_de(p, params);
    FR_COUNT(FR_COUNT_SHADOW + light_index, active, 1);
#if FR_SHADOW == FR_SHADOW_SOFT
    lit = lane_select(active, fmin(lit, (real_t)fc->shadow_softness * dist / t), lit);
#else
    lit = lane_select(active & (dist < t_start * (real_t)0.5), 0, lit);
#endif
    active &= (lit > (real_t)0.001) & (dist > (real_t)0);
    t = lane_select(active, t + fmax(dist, t_start * (real_t)0.5), t);
    active &= t < t_exit;
  }
  return clamp(lit, (real_t)0, (real_t)1);
}

/* The renderer's hook (shade.cl): start just off the surface, along the normal. */
#define FR_APPLY_SHADOWS(shadow, p, n, h, light, light_index, lanes)                         \
  shadow = shadow_factor(v3_mad(p, n, 2 * (h)), (light).to_light, 4 * (h), (light).distance, \
                         fc, params, lanes, light_index FR_COUNTS_ARG)
