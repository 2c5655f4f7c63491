/* fr/mandelbulb.cl — the power-n Mandelbulb (White and Nylander's triplex power).
 *
 * z <- z^n + p in spherical form, with the running derivative dr <- n r^(n-1) dr + 1, and the
 * escape-time estimate 0.5 r ln r / dr — accurate near the set, an over-estimate far from it, so
 * march only inside a bounding sphere (the set lies inside |p| <= 2^(1/(n-1))). Each lane stops
 * once it escapes (its values are frozen), so every lane computes exactly the scalar formula.
 * *trap receives the orbit trap min |z|^2 over the orbit, for colouring. */

real_t de_mandelbulb(vec3_t p, real_t power, real_t bailout, int iterations, real_t* trap) {
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t r = v3_length(z);
  real_t orbit_min = r * r;
  for (int i = 0; i < iterations; ++i) {
    mask_t live = r < bailout;
    if (!any_lane(live)) break;
    /* At r = 0 every angle is as good as another; keep acos's argument in [-1, 1] even where
     * rounding gives |z.z| > r. atan2(0, 0) is 0, so the polar axis is finite. */
    real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON * FR_SCALAR_EPSILON));
    real_t theta = acos(clamp(z.z / safe_r, to_real(-1), to_real(1))) * power;
    real_t phi = atan2(z.y, z.x) * power;
    real_t r_pow = pow_nonneg(safe_r, power - to_real(1));
    dr = lane_select(live, power * r_pow * dr + to_real(1), dr);
    real_t zr = r_pow * r;
    real_t sin_theta = fast_sin(theta);
    vec3_t next =
        v3(zr * sin_theta * fast_cos(phi), zr * sin_theta * fast_sin(phi), zr * fast_cos(theta));
    z = v3_select(live, v3_add(next, p), z);
    r = lane_select(live, v3_length(z), r);
    orbit_min = lane_select(live, fmin(orbit_min, r * r), orbit_min);
  }
  *trap = orbit_min;
  /* r ln r -> 0 as r -> 0: keep the origin finite (log(0) * 0 would be NaN). */
  real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON));
  return to_real(0.5) * log(safe_r) * r / dr;
}
