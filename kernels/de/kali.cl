/* fr/kali.cl — Kali's formulas (Pablo Roman Andrioli, fractalforums.com): the Kalibox (2011), a
 * Mandelbox relative whose box fold is replaced by abs(z) + translation, which breaks the box's
 * mirror symmetry into towers, spirals and lace.
 *
 * One step: rotate (an isometry), z <- |z| + t (1-Lipschitz), the Mandelbox sphere fold with
 * fixed radius 1 written as one factor f = clamp(max(min_radius2 / r^2, min_radius2), 0, 1)
 * (min_radius2 <= r^2 <= 1: inversion; inside: uniform scaling; beyond 1: none) and scaled by
 * scale / min_radius2, then z <- that + c. The derivative dr follows with the same factors
 * (and +1, as in Kali's own formula, which only makes the estimate smaller), and the estimate is
 * Rrrola's (|z| - |scale - 1|) / dr - |scale|^(1 - n) (fractalforums.com, "Mandelbox
 * optimizations", 2010). */
#include "fr/operators.cl"

real_t de_kalibox(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius2,
                  vec3_t translation, vec3_t c, scalar_t angle_x, scalar_t angle_y,
                  scalar_t angle_z, real_t* trap) {
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t orbit_min = v3_length2(z);
  const real_t s = to_real(scale / min_radius2);
  const real_t s_abs = to_real(fabs(scale) / min_radius2);
  real_t r2 = orbit_min;
  for (int i = 0; i < iterations; ++i) {
    /* A lane far out has escaped: freeze it (the estimate stays a bound, and nothing overflows). */
    const mask_t live = r2 < to_real(1e10);
    if (!any_lane(live)) break;
    vec3_t q = p_rotate_xyz(z, angle_x, angle_y, angle_z);
    q = v3_add(v3_abs(q), translation);
    const real_t q2 = fmax(v3_length2(q), to_real(1e-30));
    const real_t f = clamp(fmax(to_real(min_radius2) / q2, to_real(min_radius2)), to_real(0),
                           to_real(1));
    z = v3_select(live, v3_add(v3_scale(q, f * s), c), z);
    dr = lane_select(live, dr * f * s_abs + to_real(1), dr);
    r2 = lane_select(live, v3_length2(z), r2);
    orbit_min = lane_select(live, fmin(orbit_min, r2), orbit_min);
  }
  *trap = orbit_min;
  return (sqrt(r2) - to_real(fabs(scale - 1))) / dr -
         to_real(pown_scalar(1 / (scalar_t)fabs(scale), iterations - 1));
}
