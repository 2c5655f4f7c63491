/* lens.cl — depth of field with a thin lens: points at the focus distance stay sharp; each sample
 * moves the ray's origin to a random point of the aperture (different per pixel and sample), a
 * disc of radius aperture_radius or a regular polygon of aperture_blades sides inscribed in it,
 * and the accumulation over samples blurs the rest into the aperture's shape. */

ray_t thin_lens(ray_t ray, real_t px, real_t py, __constant const fr_frame_constants* fc) {
  const lane_uint_t ix = image_pixel_x(fc, px), iy = image_pixel_y(fc, py);
  real_t u1 = pixel_random(fc, ix, iy, 1U);
  real_t u2 = pixel_random(fc, ix, iy, 2U);
  real_t a, b; /* the point of the aperture, in units of its radius */
  const int blades = fc->aperture_blades;
  if (blades >= 3) {
    /* A regular polygon with a vertex at the top: one of its triangles (centre, vertex j,
     * vertex j + 1), each with the odds of its area, then a uniform point of it. */
    const real_t pick = u2 * (real_t)blades;
    const real_t j = floor(pick);
    const real_t v = pick - j; /* uniform again, within triangle j */
    const real_t step = (real_t)(2 * M_PI_F) / (real_t)blades;
    const real_t a0 = (real_t)(0.5f * M_PI_F) + j * step, a1 = a0 + step;
    const real_t s = sqrt(u1); /* distance from the centre, as a share of the way to the edge */
    a = s * ((real_t)1 - v) * cos(a0) + s * v * cos(a1);
    b = s * ((real_t)1 - v) * sin(a0) + s * v * sin(a1);
  } else {
    const real_t radius = sqrt(u1);
    const real_t angle = (real_t)(2 * M_PI_F) * u2;
    a = radius * cos(angle);
    b = radius * sin(angle);
  }
  const real_t radius = (real_t)fc->aperture_radius;
  vec3_t offset = v3_add(v3_scale(v3_from_float4(fc->camera_right), radius * a),
                         v3_scale(v3_from_float4(fc->camera_up), radius * b));
  real_t along = v3_dot(ray.dir, v3_from_float4(fc->camera_forward));
  vec3_t focus = v3_mad(ray.origin, ray.dir, (real_t)fc->focus_distance / along);
  ray.origin = v3_add(ray.origin, offset);
  ray.dir = v3_normalize(v3_sub(focus, ray.origin));
  return ray;
}

#define FR_APPLY_LENS(ray, px, py) ray = thin_lens(ray, px, py, fc)
