/* shadow.cl — soft shadow towards a directional light: march from the surface and keep the
 * smallest ratio k * d / t (the penumbra estimate). Result in [0, 1]: 1 is fully lit. */

real_t soft_shadow(vec3_t origin, vec3_t to_light, real_t t_start,
                   __constant const fr_frame_constants* fc,
                   __constant const scene_params_t* params, mask_t lanes) {
  ray_t ray;
  ray.origin = origin;
  ray.dir = to_light;
  real_t t_enter, t_exit;
  intersect_bounds(ray, fc->bounding_radius, &t_enter, &t_exit);
  real_t t = t_start;
  real_t lit = (real_t)1;
  const real_t k = (real_t)fc->shadow_softness;
  mask_t active = lanes & (t < t_exit);
  for (int i = 0; i < fc->shadow_max_steps && any_lane(active); ++i) {
    vec3_t p = v3_mad(origin, to_light, t);
    real_t dist = scene_de(p, params);
    lit = lane_select(active, fmin(lit, k * dist / t), lit);
    active &= (lit > (real_t)0.001) & (dist > (real_t)0);
    t = lane_select(active, t + fmax(dist, t_start), t);
    active &= t < t_exit;
  }
  return clamp(lit, (real_t)0, (real_t)1);
}

/* The renderer's hook (render.cl): start just off the surface, along the normal. */
#define FR_APPLY_SHADOWS(shadow, p, n, h, m)                                                   \
  shadow = soft_shadow(v3_mad(p, n, 2 * (h)), v3_from_float4(fc->to_light), 4 * (h), fc, params, \
                       (m).hit)
