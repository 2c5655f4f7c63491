/* shade.cl — surface and sky colour: one directional light, Lambert diffuse plus Blinn-Phong
 * specular, ambient term scaled by occlusion. Linear RGB, unbounded (tonemapped in post.cl). */

vec3_t sky_color(vec3_t dir, __constant const fr_frame_constants* fc) {
  real_t up = clamp(v3_dot(dir, v3_from_float4(fc->sky_up)), (real_t)0, (real_t)1);
  vec3_t horizon = v3_from_float4(fc->sky_horizon);
  vec3_t zenith = v3_from_float4(fc->sky_zenith);
  return v3_mad(v3_scale(horizon, (real_t)1 - up), zenith, up);
}

vec3_t shade_surface(vec3_t normal, vec3_t view_dir, real_t shadow, real_t ao,
                     __constant const fr_frame_constants* fc) {
  vec3_t to_light = v3_from_float4(fc->to_light);
  real_t lambert = fmax(v3_dot(normal, to_light), (real_t)0);
  vec3_t half_vec = v3_normalize(v3_sub(to_light, view_dir));
  real_t spec_base = fmax(v3_dot(normal, half_vec), (real_t)0);
  real_t specular = lane_select(lambert > (real_t)0,
                                (real_t)fc->specular_strength *
                                    pow_nonneg(spec_base, (real_t)fc->specular_power),
                                0);
  vec3_t albedo = v3_from_float4(fc->albedo);
  vec3_t light = v3_from_float4(fc->light_color);
  vec3_t ambient = v3_from_float4(fc->ambient_color);
  vec3_t diffuse = v3_mad(v3_scale(ambient, ao), light, lambert * shadow);
  vec3_t color = v3_mul(albedo, diffuse);
  return v3_mad(color, light, specular * shadow);
}
