/* mandelbulb.cl — the power-n Mandelbulb (White and Nylander's triplex power), lane-generic.
 *
 * z <- z^n + p in spherical form, with the running derivative dr <- n r^(n-1) dr + 1, and the
 * escape-time distance estimate 0.5 r ln r / dr. Each lane stops iterating once it escapes
 * (its values are frozen by lane_select), so all lanes see exactly the scalar formula. */

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  const real_t power = to_real(PARAM(power));
  const real_t bailout = to_real(PARAM(bailout));
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t r = v3_length(z);
  for (int i = 0; i < PARAM(iterations); ++i) {
    mask_t live = r < bailout;
    if (!any_lane(live)) break;
    /* At r = 0 (the origin) every angle is as good as another; keep acos's argument in [-1, 1]
     * even where rounding gives |z.z| > r. atan2(0, 0) is 0, so the polar axis is finite. */
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
  }
  /* r ln r -> 0 as r -> 0: keep the origin finite (log(0) * 0 would be NaN). */
  real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON));
  return to_real(0.5) * log(safe_r) * r / dr;
}
