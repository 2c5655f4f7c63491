/* fr/julia.cl — the quaternion Julia set z <- z^2 + c, sliced at w = slice_w.
 *
 * A quaternion (x, y, z, w) with x the real part squares to (x^2 - |v|^2, 2 x v). Since
 * |q r| = |q| |r| for quaternions, the derivative's size follows dr <- 2 |z| dr, and the estimate
 * is 0.5 |z| ln|z| / dr. The filled set lies inside |p| <= (1 + sqrt(1 + 4 |c|)) / 2. With c = 0
 * the set is the unit ball and the estimate is exactly 0.5 |p| ln|p|. Lanes stop at the bailout,
 * and also once |z| < 1e-4 (deep inside, where |z|^(2^n) would underflow and turn the estimate
 * into NaN). *trap receives min |z|^2 over the orbit. */

real_t de_julia_quaternion(vec3_t p, scalar_t slice_w, vec3_t c_xyz, scalar_t c_w, real_t bailout,
                           int iterations, real_t* trap) {
  real_t zx = p.x, zy = p.y, zz = p.z, zw = to_real(slice_w);
  real_t r = sqrt(zx * zx + zy * zy + zz * zz + zw * zw);
  real_t dr = to_real(1);
  real_t orbit_min = r * r;
  for (int i = 0; i < iterations; ++i) {
    mask_t live = (r < bailout) & (r > to_real(1e-4));
    if (!any_lane(live)) break;
    real_t nx = zx * zx - zy * zy - zz * zz - zw * zw + c_xyz.x;
    real_t ny = 2 * zx * zy + c_xyz.y;
    real_t nz = 2 * zx * zz + c_xyz.z;
    real_t nw = 2 * zx * zw + to_real(c_w);
    dr = lane_select(live, 2 * r * dr, dr);
    zx = lane_select(live, nx, zx);
    zy = lane_select(live, ny, zy);
    zz = lane_select(live, nz, zz);
    zw = lane_select(live, nw, zw);
    r = lane_select(live, sqrt(zx * zx + zy * zy + zz * zz + zw * zw), r);
    orbit_min = lane_select(live, fmin(orbit_min, r * r), orbit_min);
  }
  *trap = orbit_min;
  real_t safe_r = fmax(r, to_real(FR_SCALAR_MIN));
  return to_real(0.5) * r * log(safe_r) / fmax(dr, to_real(FR_SCALAR_MIN));
}

/* The quaternion Mandelbrot set, sliced: q <- q^2 + c with c = (p, slice_w) and q starting at 0
 * (so q_1 = c). The derivative with respect to c follows dr <- 2 |q| dr + 1, and the estimate
 * is 0.5 |q| ln|q| / dr as for the Julia set. With slice_w = 0 the slice through the plane
 * y = z = 0 is the classic Mandelbrot set (the x axis the real one), spun about that axis:
 * q^2 only mixes the real part with the whole imaginary vector, so the set is symmetric under
 * rotations of (y, z, w). The set lies inside |c| <= 2. *trap receives min |q|^2. */
real_t de_quaternion_mandelbrot(vec3_t p, scalar_t slice_w, real_t bailout, int iterations,
                                real_t* trap) {
  real_t zx = p.x, zy = p.y, zz = p.z, zw = to_real(slice_w);
  real_t r = sqrt(zx * zx + zy * zy + zz * zz + zw * zw);
  real_t dr = to_real(1);
  real_t orbit_min = r * r;
  for (int i = 1; i < iterations; ++i) {
    mask_t live = r < bailout;
    if (!any_lane(live)) break;
    real_t nx = zx * zx - zy * zy - zz * zz - zw * zw + p.x;
    real_t ny = 2 * zx * zy + p.y;
    real_t nz = 2 * zx * zz + p.z;
    real_t nw = 2 * zx * zw + to_real(slice_w);
    dr = lane_select(live, 2 * r * dr + to_real(1), dr);
    zx = lane_select(live, nx, zx);
    zy = lane_select(live, ny, zy);
    zz = lane_select(live, nz, zz);
    zw = lane_select(live, nw, zw);
    r = lane_select(live, sqrt(zx * zx + zy * zy + zz * zz + zw * zw), r);
    orbit_min = lane_select(live, fmin(orbit_min, r * r), orbit_min);
  }
  *trap = orbit_min;
  real_t safe_r = fmax(r, to_real(FR_SCALAR_EPSILON));
  return to_real(0.5) * r * log(safe_r) / dr;
}
