/* shade.cl — sky and surface colour. The surface sums every light through the shading model
 * FR_SHADING picks, plus ambient light scaled by occlusion:
 *   FR_SHADING_LAMBERT      Lambert: albedo * cos(theta_i)
 *   FR_SHADING_BLINN_PHONG  Blinn-Phong: Lambert + specular_strength * (n.h)^specular_power
 *   FR_SHADING_OREN_NAYAR   Oren-Nayar: rough diffuse, albedo * cos(theta_i) * (A + B max(0, cos(phi_i - phi_r))
 *      sin(alpha) tan(beta)) with A = 1 - 0.5 s^2/(s^2 + 0.33), B = 0.45 s^2/(s^2 + 0.09),
 *      alpha = max(theta_i, theta_r), beta = min(...), s = roughness; plus Blinn-Phong specular
 *      weighted by Schlick's Fresnel term F = f0 + (1 - f0)(1 - h.v)^5, the diffuse by 1 - F.
 * Linear RGB, unbounded (tonemapped in post.cl). */

#ifndef FR_APPLY_SHADOWS
#define FR_APPLY_SHADOWS(shadow, p, n, h, lights, facing, count, max_steps)
#endif

/* The surface at p: the scene's surface source, or the default material (the settings'). */
#if FR_HAS_SURFACE
#if FR_DD
/* Points are relative to the eye (dd_relative.cl); the surface takes world coordinates. */
#define surface_at(p) scene_surface(fr_world_point((p), params), params)
#else
#define surface_at(p) scene_surface(p, params)
#endif
#else
inline surface_t default_surface(__constant const fr_frame_constants* fc) {
  surface_t s;
  s.albedo = v3_from_float4(fc->albedo);
  s.reflectivity = (real_t)fc->reflectivity;
  return s;
}
#define surface_at(p) default_surface(fc)
#endif

vec3_t sky_color(vec3_t dir, __constant const fr_frame_constants* fc) {
  real_t up = clamp(v3_dot(dir, v3_from_float4(fc->sky_up)), (real_t)0, (real_t)1);
  vec3_t horizon = v3_from_float4(fc->sky_horizon);
  vec3_t zenith = v3_from_float4(fc->sky_zenith);
  return v3_mad(v3_scale(horizon, (real_t)1 - up), zenith, up);
}
/* The sky a ray sees when it leaves the scene: the gradient, or the panorama (environment.cl). */
#ifndef FR_SKY
#define FR_SKY(dir) sky_color(dir, fc)
#endif

/* Reflected radiance per unit incoming radiance, times cos(theta_i), for one light. */
vec3_t brdf_cos(vec3_t n, vec3_t to_light, vec3_t to_eye, vec3_t albedo, real_t n_dot_l,
                __constant const fr_frame_constants* fc) {
  real_t lambert = fmax(n_dot_l, (real_t)0);
#if FR_SHADING == FR_SHADING_LAMBERT
  return v3_scale(albedo, lambert);
#else
  vec3_t half_vec = v3_normalize(v3_add(to_light, to_eye));
  real_t spec = (real_t)fc->specular_strength *
                pow_nonneg(fmax(v3_dot(n, half_vec), (real_t)0), (real_t)fc->specular_power);
  spec = lane_select(lambert > 0, spec * lambert, 0);
#if FR_SHADING == FR_SHADING_BLINN_PHONG
  return v3_add(v3_scale(albedo, lambert), v3(spec, spec, spec));
#else
  const real_t s2 = (real_t)(fc->roughness * fc->roughness);
  const real_t a = (real_t)1 - (real_t)0.5 * s2 / (s2 + (real_t)0.33);
  const real_t b = (real_t)0.45 * s2 / (s2 + (real_t)0.09);
  real_t n_dot_v = clamp(v3_dot(n, to_eye), (real_t)0, (real_t)1);
  real_t cos_i = clamp(n_dot_l, (real_t)0, (real_t)1);
  /* cos(phi_i - phi_r): the angle between the light and eye directions projected on the
   * tangent plane. */
  vec3_t li = v3_normalize(v3_mad(to_light, n, -cos_i));
  vec3_t lr = v3_normalize(v3_mad(to_eye, n, -n_dot_v));
  real_t cos_phi = fmax(v3_dot(li, lr), (real_t)0);
  real_t cos_alpha = fmin(cos_i, n_dot_v), cos_beta = fmax(cos_i, n_dot_v);
  real_t sin_alpha = sqrt(fmax((real_t)1 - cos_alpha * cos_alpha, (real_t)0));
  real_t tan_beta = sqrt(fmax((real_t)1 - cos_beta * cos_beta, (real_t)0)) /
                    fmax(cos_beta, (real_t)1e-4);
  real_t oren_nayar = lambert * (a + b * cos_phi * sin_alpha * tan_beta);
  real_t h_dot_v = clamp(v3_dot(half_vec, to_eye), (real_t)0, (real_t)1);
  real_t one_minus = (real_t)1 - h_dot_v;
  real_t m5 = one_minus * one_minus * one_minus * one_minus * one_minus;
  real_t fresnel = (real_t)fc->fresnel_f0 + (real_t)(1 - fc->fresnel_f0) * m5;
  real_t diffuse = oren_nayar * ((real_t)1 - fresnel);
  real_t specular = spec * fresnel;
  return v3_add(v3_scale(albedo, diffuse), v3(specular, specular, specular));
#endif
#endif
}

/* The colour of the surface at p seen along view_dir, and the first light's shadow factor; its
 * shadow rays march at most shadow_steps each (the primary rays' budget or a bounce's). */
vec3_t shade_surface(vec3_t p, vec3_t n, vec3_t view_dir, surface_t surface, real_t ao, real_t h,
                     mask_t lanes, int shadow_steps, __constant const fr_frame_constants* fc,
                     __constant const scene_params_t* params,
                     real_t* first_shadow FR_COUNTS_PARAM) {
  vec3_t to_eye = v3_neg(view_dir);
  vec3_t color = v3_mul(surface.albedo, v3_scale(v3_from_float4(fc->ambient_color), ao));
  light_sample_t lights[FR_MAX_LIGHTS];
  mask_t facing[FR_MAX_LIGHTS];
  real_t shadow[FR_MAX_LIGHTS];
  const int count = min(fc->light_count, FR_MAX_LIGHTS);
  for (int i = 0; i < count; ++i) {
    lights[i] = sample_light(i, p, fc);
    facing[i] = lanes & (v3_dot(n, lights[i].to_light) > (real_t)0);
    shadow[i] = (real_t)1;
  }
  FR_APPLY_SHADOWS(shadow, p, n, h, lights, facing, count, shadow_steps);
  *first_shadow = (real_t)1;
  for (int i = 0; i < count; ++i) {
    const real_t lit = lane_select(facing[i], shadow[i], 0);
    if (i == 0) *first_shadow = lit;
    if (!any_lane(facing[i])) continue;
    const real_t n_dot_l = v3_dot(n, lights[i].to_light);
    vec3_t reflected = brdf_cos(n, lights[i].to_light, to_eye, surface.albedo, n_dot_l, fc);
    color = v3_add(color, v3_scale(v3_mul(reflected, lights[i].radiance), lit));
  }
  return color;
}
