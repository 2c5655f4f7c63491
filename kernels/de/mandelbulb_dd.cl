/* fr/mandelbulb_dd.cl — the power-n Mandelbulb (fr/mandelbulb.cl, White and Nylander's triplex
 * power) at a point given in double-double (fr/dd.cl), for views past what double resolves.
 *
 * The same iteration, z <- z^n + p with dr <- n r^(n-1) dr + 1 and the estimate 0.5 r ln r / dr,
 * for a whole power n (1 to 64): the triplex power needs no trigonometry there, only the cosines
 * and sines of theta and phi read off z (quotients and square roots of pairs) turned n times by de
 * Moivre's formula, as the double form's whole-number path does. A rounding of z at an iteration
 * where the running derivative is dr moves the estimate's point by that rounding over dr, so the
 * rest may run in double once dr x resolution exceeds 1000 ulps of max(|z|, |p|). Unlike the
 * Mandelbox's, the bulb's dr can shrink again (where |z| < 1, n r^(n-1) < 1): the double part
 * keeps checking the same bound at every later iteration, and a lane that falls below it is
 * evaluated again with every iteration in pairs. A fractional power has no pair form here (its
 * angles need trigonometry in pairs): it runs the double estimate at the point rounded to
 * double, which is right only where double resolves the view. */
#include "fr/dd.cl"
#include "fr/mandelbulb.cl"

/* (c + i s)^n for a whole n >= 1, in pairs, by repeated squaring (unit_complex_pow_int's). */
inline void dd_unit_complex_pow_int(dd_t* c, dd_t* s, int n) {
  dd_t base_c = *c, base_s = *s;
  while (!(n & 1)) {
    const dd_t square_c = dd_sub(dd_mul(base_c, base_c), dd_mul(base_s, base_s));
    base_s = dd_mul_d(dd_mul(base_c, base_s), to_real(2));
    base_c = square_c;
    n >>= 1;
  }
  dd_t result_c = base_c, result_s = base_s;
  for (n >>= 1; n > 0; n >>= 1) {
    const dd_t square_c = dd_sub(dd_mul(base_c, base_c), dd_mul(base_s, base_s));
    base_s = dd_mul_d(dd_mul(base_c, base_s), to_real(2));
    base_c = square_c;
    if (n & 1) {
      const dd_t next_c = dd_sub(dd_mul(result_c, base_c), dd_mul(result_s, base_s));
      result_s = dd_add(dd_mul(result_c, base_s), dd_mul(result_s, base_c));
      result_c = next_c;
    }
  }
  *c = result_c;
  *s = result_s;
}

/* x^n for a whole n >= 1, in pairs. */
inline dd_t dd_pow_int(dd_t x, int n) {
  while (!(n & 1)) {
    x = dd_mul(x, x);
    n >>= 1;
  }
  dd_t result = x;
  for (n >>= 1; n > 0; n >>= 1) {
    x = dd_mul(x, x);
    if (n & 1) result = dd_mul(result, x);
  }
  return result;
}

/* One triplex power z^n in pairs; *r_pow receives r^(n-1) (rounded: it only feeds dr). */
inline dd3_t dd_mandelbulb_pow_int(dd3_t z, int n, real_t* r_pow) {
  const dd_t rho2 = dd_add(dd_mul(z.x, z.x), dd_mul(z.y, z.y));
  const dd_t r2 = dd_add(rho2, dd_mul(z.z, z.z));
  const dd_t r = dd_sqrt(r2), rho = dd_sqrt(rho2);
  /* At r = 0 every direction is as good as another (z^n = 0); on the polar axis phi is
   * irrelevant (sin(n theta) = 0), as the double form takes it. */
  const mask_t at_origin = r.hi <= to_real(FR_SCALAR_MIN);
  const mask_t on_axis = rho.hi <= to_real(FR_SCALAR_MIN);
  const dd_t safe_r = dd_select(at_origin, dd_from(to_real(1)), r);
  const dd_t safe_rho = dd_select(on_axis, dd_from(to_real(1)), rho);
  const dd_t inv_r = dd_div_d_by(to_real(1), safe_r), inv_rho = dd_div_d_by(to_real(1), safe_rho);
  dd_t cos_theta = dd_select(at_origin, dd_from(to_real(1)), dd_mul(z.z, inv_r));
  dd_t sin_theta = dd_select(at_origin, dd_from(to_real(0)), dd_mul(rho, inv_r));
  dd_t cos_phi = dd_select(on_axis, dd_from(to_real(1)), dd_mul(z.x, inv_rho));
  dd_t sin_phi = dd_select(on_axis, dd_from(to_real(0)), dd_mul(z.y, inv_rho));
  dd_unit_complex_pow_int(&cos_theta, &sin_theta, n);
  dd_unit_complex_pow_int(&cos_phi, &sin_phi, n);
  const dd_t zr = dd_pow_int(r, n);
  *r_pow = n > 1 ? dd_to_real(dd_pow_int(r, n - 1)) : to_real(1);
  const dd_t xy = dd_mul(zr, sin_theta);
  return dd3_make(dd_mul(xy, cos_phi), dd_mul(xy, sin_phi), dd_mul(zr, cos_theta));
}

/* The whole-power bulb at p: pairs while dr x resolution is below the bound, double after; sets
 * *short_of where a lane's later double iterations fell below the bound again. */
inline real_t dd_mandelbulb_whole(dd3_t p, int n, real_t bailout, int iterations,
                                  real_t resolution, mask_t* short_of) {
  const real_t switch_ulps = to_real(1000 * DBL_EPSILON);
  const real_t p_size = sqrt(v3_length2(dd3_to_v3(p)));
  dd3_t z = p;
  real_t dr = to_real(1);
  real_t r = p_size;
  int i = 0;
  for (; i < iterations; ++i) {
    const mask_t live = r < bailout;
    if (!any_lane(live)) break;
    const mask_t needs_pairs = dr * resolution <= switch_ulps * fmax(r, p_size);
    if (!any_lane(live & needs_pairs)) break; /* the rest in double, below */
    real_t r_pow;
    const dd3_t next = dd3_add(dd_mandelbulb_pow_int(z, n, &r_pow), p);
    dr = lane_select(live, to_real(n) * r_pow * dr + to_real(1), dr);
    z = dd3_select(live, next, z);
    r = lane_select(live, sqrt(v3_length2(dd3_to_v3(z))), r);
  }
  /* A lane whose orbit ended in pairs takes r from the pairs (as fr/mandelbox_dd.cl says why),
   * and 0.5 r ln r to first order in r's low part. */
  const mask_t ended_in_pairs = i >= iterations ? FR_MASK_TRUE : (r >= bailout);
  const dd_t r_pairs = dd_sqrt(dd3_length2(z));
  vec3_t zd = dd3_to_v3(z);
  const vec3_t pd = dd3_to_v3(p);
  *short_of = FR_MASK_FALSE;
  for (; i < iterations; ++i) {
    const mask_t live = r < bailout;
    if (!any_lane(live)) break;
    *short_of |= live & (dr * resolution <= switch_ulps * fmax(r, p_size));
    real_t r_pow;
    const vec3_t next = mandelbulb_pow_int(zd, r, n, &r_pow);
    dr = lane_select(live, to_real(n) * r_pow * dr + to_real(1), dr);
    zd = v3_select(live, v3_add(next, pd), zd);
    r = lane_select(live, v3_length(zd), r);
  }
  const real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON));
  const real_t safe_hi = fmax(r_pairs.hi, to_real(FR_SCALAR_EPSILON));
  const real_t log_hi = log(safe_hi);
  const real_t from_pairs =
      to_real(0.5) * (log_hi * r_pairs.hi + (log_hi + to_real(1)) * r_pairs.lo) / dr;
  return lane_select(ended_in_pairs, from_pairs, to_real(0.5) * log(safe_r) * r / dr);
}

real_t de_mandelbulb_dd(dd3_t p, float power, real_t bailout, int iterations,
                        real_t resolution) {
  const bool whole_power = power == rint(power) && power >= 1.0f && power <= 64.0f;
  if (!whole_power) {
    real_t trap;
    return de_mandelbulb(dd3_to_v3(p), power, bailout, iterations, &trap);
  }
  mask_t short_of;
  real_t d = dd_mandelbulb_whole(p, (int)power, bailout, iterations, resolution, &short_of);
  if (any_lane(short_of)) {
    mask_t unused;
    d = lane_select(short_of,
                    dd_mandelbulb_whole(p, (int)power, bailout, iterations, to_real(0), &unused),
                    d);
  }
  return d;
}
