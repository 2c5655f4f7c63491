/* lens.cl — depth of field with a thin lens: points at the focus distance stay sharp; each sample
 * moves the ray's origin to a random point of the aperture disc (different per pixel and sample),
 * and the accumulation over samples blurs the rest. */

ray_t thin_lens(ray_t ray, real_t px, real_t py, __constant const fr_frame_constants* fc) {
  const lane_uint_t ix = image_pixel_x(fc, px), iy = image_pixel_y(fc, py);
  real_t u1 = pixel_random(fc, ix, iy, 1U);
  real_t u2 = pixel_random(fc, ix, iy, 2U);
  real_t radius = (real_t)fc->aperture_radius * sqrt(u1);
  real_t angle = (real_t)(2 * M_PI_F) * u2;
  vec3_t offset = v3_add(v3_scale(v3_from_float4(fc->camera_right), radius * cos(angle)),
                         v3_scale(v3_from_float4(fc->camera_up), radius * sin(angle)));
  real_t along = v3_dot(ray.dir, v3_from_float4(fc->camera_forward));
  vec3_t focus = v3_mad(ray.origin, ray.dir, (real_t)fc->focus_distance / along);
  ray.origin = v3_add(ray.origin, offset);
  ray.dir = v3_normalize(v3_sub(focus, ray.origin));
  return ray;
}

#define FR_APPLY_LENS(ray, px, py) ray = thin_lens(ray, px, py, fc)
