/* fr/mandelbulb.cl — the power-n Mandelbulb (White and Nylander's triplex power).
 *
 * z <- z^n + p in spherical form, with the running derivative dr <- n r^(n-1) dr + 1, and the
 * escape-time estimate 0.5 r ln r / dr — accurate near the set, an over-estimate far from it, so
 * march only inside a bounding sphere (the set lies inside |p| <= 2^(1/(n-1))). Each lane stops
 * once it escapes (its values are frozen), so every lane computes exactly the scalar formula.
 * *trap receives the orbit trap min |z|^2 over the orbit, for colouring.
 *
 * `power` is one value for all lanes (a scene parameter). When it is a whole number — the
 * classic n = 8 — the angles are multiplied without any trigonometry: with cos/sin of theta and
 * phi read off z directly, cos(n a) + i sin(n a) = (cos a + i sin a)^n (de Moivre) by repeated
 * squaring, and r^(n-1) by multiplication. Same formula, no less accurate, and several times
 * cheaper on a CPU than acos, atan2, pow and four sin/cos per iteration. A fractional power
 * (animated, say) takes the trigonometric path. */

#include "fr/powers.cl"

/* One triplex power z^n of the whole-number path: returns z^n and sets *r_pow = r^(n-1). Always
 * inlined: PoCL 3.1 left it a call, its vectors passed through memory, and the reference view
 * took 1.13x as long. */
__attribute__((always_inline)) inline vec3_t mandelbulb_pow_int(vec3_t z, real_t r, int n,
                                                                real_t* r_pow) {
  real_t safe_r = fmax(r, to_real(FR_SCALAR_MIN));
  real_t rho = sqrt(z.x * z.x + z.y * z.y);
  /* theta = acos(z.z / r) lies in [0, pi], so its sine is rho / r >= 0. */
  real_t inv_r = to_real(1) / safe_r;
  real_t cos_theta = clamp(z.z * inv_r, to_real(-1), to_real(1));
  real_t sin_theta = fmin(rho * inv_r, to_real(1));
  /* On the polar axis phi is undefined, and irrelevant: sin(n theta) = 0 there, so z^n has no
   * x or y part whatever phi is. Take phi = 0, as atan2(0, 0) does. */
  mask_t on_axis = rho <= to_real(FR_SCALAR_MIN);
  real_t inv_rho = to_real(1) / fmax(rho, to_real(FR_SCALAR_MIN));
  real_t cos_phi = lane_select(on_axis, to_real(1), z.x * inv_rho);
  real_t sin_phi = lane_select(on_axis, to_real(0), z.y * inv_rho);
  unit_complex_pow_int(&cos_theta, &sin_theta, n);
  unit_complex_pow_int(&cos_phi, &sin_phi, n);
  *r_pow = pow_int(safe_r, n - 1);
  real_t zr = *r_pow * r;
  return v3(zr * sin_theta * cos_phi, zr * sin_theta * sin_phi, zr * cos_theta);
}

/* The same triplex power for any real n, through the angles. */
inline vec3_t mandelbulb_pow_real(vec3_t z, real_t r, real_t power, real_t* r_pow) {
  /* At r = 0 every angle is as good as another; keep acos's argument in [-1, 1] even where
   * rounding gives |z.z| > r. atan2(0, 0) is 0, so the polar axis is finite. */
  real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON * FR_SCALAR_EPSILON));
  real_t theta = acos(clamp(z.z / safe_r, to_real(-1), to_real(1))) * power;
  real_t phi = atan2(z.y, z.x) * power;
  *r_pow = pow_nonneg(safe_r, power - to_real(1));
  real_t zr = *r_pow * r;
  real_t sin_theta = fast_sin(theta);
  return v3(zr * sin_theta * fast_cos(phi), zr * sin_theta * fast_sin(phi), zr * fast_cos(theta));
}

real_t de_mandelbulb(vec3_t p, float power, real_t bailout, int iterations, real_t* trap) {
  /* Up to 64 the whole-number path is exact arithmetic on unit vectors; beyond that r^n
   * overflows float anyway. */
  bool whole_power = power == rint(power) && power >= 1.0f && power <= 64.0f;
  int power_int = (int)power;
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t r = v3_length(z);
  real_t orbit_min = r * r;
  for (int i = 0; i < iterations; ++i) {
    mask_t live = r < bailout;
    if (!any_lane(live)) break;
    real_t r_pow;
    vec3_t next = whole_power ? mandelbulb_pow_int(z, r, power_int, &r_pow)
                              : mandelbulb_pow_real(z, r, to_real(power), &r_pow);
    dr = lane_select(live, to_real(power) * r_pow * dr + to_real(1), dr);
    z = v3_select(live, v3_add(next, p), z);
    r = lane_select(live, v3_length(z), r);
    orbit_min = lane_select(live, fmin(orbit_min, r * r), orbit_min);
  }
  *trap = orbit_min;
  /* r ln r -> 0 as r -> 0: keep the origin finite (log(0) * 0 would be NaN). */
  real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON));
  return to_real(0.5) * log(safe_r) * r / dr;
}

/* The bulb's variants on one loop: `julia` adds the constant c instead of p (the Juliabulb: dr
 * then gets no +1, and lanes at the origin stop, where r ln r / dr is 0/0), `burning` folds z
 * into the positive octant before each power (the Burning Ship's abs, Michelitsch and Rossler,
 * 1992, applied to the bulb: an isometry on each side of the planes, so dr is unchanged).
 * The Mandelbulb itself keeps its own loop above: it is the benchmark's hot path. */
__attribute__((always_inline)) inline real_t bulb_iterate(vec3_t p, float power, vec3_t c,
                                                          int julia, int burning, real_t bailout,
                                                          int iterations, real_t* trap) {
  bool whole_power = power == rint(power) && power >= 1.0f && power <= 64.0f;
  int power_int = (int)power;
  const vec3_t added = julia ? c : p;
  const real_t dr_added = julia ? to_real(0) : to_real(1);
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t r = v3_length(z);
  real_t orbit_min = r * r;
  for (int i = 0; i < iterations; ++i) {
    mask_t live = julia ? (r < bailout) & (r > to_real(1e-4)) : r < bailout;
    if (!any_lane(live)) break;
    const vec3_t base = burning ? v3_abs(z) : z;
    real_t r_pow;
    vec3_t next = whole_power ? mandelbulb_pow_int(base, r, power_int, &r_pow)
                              : mandelbulb_pow_real(base, r, to_real(power), &r_pow);
    dr = lane_select(live, to_real(power) * r_pow * dr + dr_added, dr);
    z = v3_select(live, v3_add(next, added), z);
    r = lane_select(live, v3_length(z), r);
    orbit_min = lane_select(live, fmin(orbit_min, r * r), orbit_min);
  }
  *trap = orbit_min;
  real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON));
  return to_real(0.5) * log(safe_r) * r / fmax(dr, to_real(FR_SCALAR_MIN));
}

/* The Mandelbulb's Julia set: z <- z^n + c. */
real_t de_juliabulb(vec3_t p, float power, vec3_t c, real_t bailout, int iterations,
                    real_t* trap) {
  return bulb_iterate(p, power, c, 1, 0, bailout, iterations, trap);
}

/* The burning bulb: z <- |z|^n + p, |z| taken coordinate by coordinate. */
real_t de_burning_bulb(vec3_t p, float power, real_t bailout, int iterations, real_t* trap) {
  return bulb_iterate(p, power, p, 0, 1, bailout, iterations, trap);
}

/* Doug Bristor's "Bristorbrot" (fractalforums.com, 2012): a quadratic triplex map without
 * trigonometry, z <- (x^2 - y^2 - z^2, y (2x - z), z (2x + y)) + p. The map is not conformal, so
 * the bulbs' scalar derivative 2 r dr undercounts its stretch; the whole Jacobian J (J <- Df(z) J
 * + I) is carried instead, and the estimate 0.5 r ln r / |J| uses its Frobenius norm, which
 * bounds the stretch in every direction. */
/* Df(z) c, Df(z) = [[2x, -2y, -2z], [2y, 2x - z, -y], [2z, z, 2x + y]]. */
inline vec3_t bristor_jacobian_times(vec3_t z, vec3_t c) {
  return v3(2 * (z.x * c.x - z.y * c.y - z.z * c.z),
            2 * z.y * c.x + (2 * z.x - z.z) * c.y - z.y * c.z,
            2 * z.z * c.x + z.z * c.y + (2 * z.x + z.y) * c.z);
}

real_t de_bristorbrot(vec3_t p, real_t bailout, int iterations, real_t* trap) {
  vec3_t z = p;
  /* J's columns: the derivatives of z along x, y and z. */
  vec3_t jx = v3s(1, 0, 0), jy = v3s(0, 1, 0), jz = v3s(0, 0, 1);
  real_t r = v3_length(z);
  real_t orbit_min = r * r;
  for (int i = 0; i < iterations; ++i) {
    mask_t live = r < bailout;
    if (!any_lane(live)) break;
    const vec3_t nx = v3_add(bristor_jacobian_times(z, jx), v3s(1, 0, 0));
    const vec3_t ny = v3_add(bristor_jacobian_times(z, jy), v3s(0, 1, 0));
    const vec3_t nz = v3_add(bristor_jacobian_times(z, jz), v3s(0, 0, 1));
    const vec3_t next = v3(z.x * z.x - z.y * z.y - z.z * z.z, z.y * (2 * z.x - z.z),
                           z.z * (2 * z.x + z.y));
    jx = v3_select(live, nx, jx);
    jy = v3_select(live, ny, jy);
    jz = v3_select(live, nz, jz);
    z = v3_select(live, v3_add(next, p), z);
    r = lane_select(live, v3_length(z), r);
    orbit_min = lane_select(live, fmin(orbit_min, r * r), orbit_min);
  }
  *trap = orbit_min;
  const real_t j_norm = sqrt(v3_length2(jx) + v3_length2(jy) + v3_length2(jz));
  real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON));
  return to_real(0.5) * log(safe_r) * r / fmax(j_norm, to_real(FR_SCALAR_MIN));
}
