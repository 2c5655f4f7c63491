/* fr/hybrid_dd.cl — the hybrid steps of fr/hybrid.cl on points given in double-double (fr/dd.cl),
 * for views past what double resolves.
 *
 * Each step does what its double form does, with z in pairs and the same double constants; dr
 * stays a double (it only scales the estimate). The bulb step has a pair form for whole powers
 * (1 to 64, fr/mandelbulb_dd.cl's de Moivre); a fractional power has none (its angles would need
 * trigonometry in pairs) and runs in double on z rounded, which the host notices (its probe of
 * the estimate's resolution, render/precision.hpp) and says. A scene runs the steps in pairs
 * while dr x resolution is below 1000 ulps of the orbit's size, then in double; since some steps
 * shrink dr (the bulb inside |z| < 1, Kali's inversion), the double part keeps checking, as
 * fr/mandelbulb_dd.cl does (plugins/hybrid/hybrid.cl shows the loop). */
#include "fr/hybrid.cl"
#include "fr/dd_folds.cl"
#include "fr/mandelbulb_dd.cl"

/* One step of kind `kind` on the lanes in `live`, in pairs (hybrid_step's). */
inline void hybrid_step_dd(int kind, mask_t live, dd3_t* z, real_t* dr, dd3_t p, scalar_t a,
                           scalar_t b, vec3_t v) {
  dd3_t q = *z;
  real_t d = *dr;
  switch (kind) {
    case HYBRID_BULB: {
      const int n = (int)a;
      real_t r_pow;
      if (a == (scalar_t)n && n >= 1 && n <= 64) {
        q = dd_mandelbulb_pow_int(q, n, &r_pow);
      } else {
        const vec3_t rounded = dd3_to_v3(q);
        q = dd3_from(mandelbulb_pow_real(rounded, v3_length(rounded), to_real(a), &r_pow));
      }
      q = dd3_add(q, p);
      d = to_real(a) * r_pow * d + to_real(1);
      break;
    }
    case HYBRID_BOX_FOLD:
      q = dd3_fold_box(q, to_real(a));
      break;
    case HYBRID_SPHERE_FOLD: {
      const dd_sphere_fold_t fold = dd_sphere_fold_prepare(a, b);
      const dd_t factor = dd_sphere_fold_factor(dd3_length2(q), &fold);
      q = dd3_scale(q, factor);
      d *= factor.hi;
      break;
    }
    case HYBRID_SCALE_TRANSLATE:
      q = dd3_add(dd3_add_v3(dd3_scale_d(q, to_real(a)), v), p);
      d = d * to_real(fabs(a)) + to_real(1);
      break;
    case HYBRID_MENGER: {
      const real_t step = to_real(a - 1);
      q = dd3_fold_menger(q);
      q.x = dd_add_d(dd_mul_d(q.x, to_real(a)), -v.x * step);
      q.y = dd_add_d(dd_mul_d(q.y, to_real(a)), -v.y * step);
      q.z = dd_mul_d(q.z, to_real(a));
      q.z = dd_select(dd_gt_d(q.z, to_real(0.5) * v.z * step), dd_add_d(q.z, -v.z * step), q.z);
      d = d * to_real(fabs(a));
      break;
    }
    case HYBRID_OCTAHEDRAL:
    case HYBRID_ICOSAHEDRAL:
    case HYBRID_TETRAHEDRAL:
      q = kind == HYBRID_OCTAHEDRAL    ? dd3_fold_menger(q)
          : kind == HYBRID_ICOSAHEDRAL ? dd3_fold_icosahedral(q)
                                       : dd3_fold_sierpinski(q);
      q = dd3_add_v3(dd3_scale_d(q, to_real(a)), v3_scale(v, -to_real(a - 1)));
      d = d * to_real(fabs(a));
      break;
    case HYBRID_ROTATE: {
      const vec3_t angles = v3_scale(v, to_real(M_PI / 180));
      q = dd3_rotate_x_cs(q, cos(angles.x), sin(angles.x));
      q = dd3_rotate_y_cs(q, cos(angles.y), sin(angles.y));
      q = dd3_rotate_z_cs(q, cos(angles.z), sin(angles.z));
      break;
    }
    case HYBRID_QUATERNION_SQUARE: {
      const real_t r = sqrt(dd_to_real(dd3_length2(q)));
      const dd_t x2 = dd_sub(dd_sub(dd_mul(q.x, q.x), dd_mul(q.y, q.y)), dd_mul(q.z, q.z));
      const dd_t two_x = dd_mul_d(q.x, to_real(2));
      q = dd3_add(dd3_make(x2, dd_mul(two_x, q.y), dd_mul(two_x, q.z)), p);
      d = 2 * r * d + to_real(1);
      break;
    }
    case HYBRID_KALI: {
      const dd_t length2 = dd3_length2(q);
      const dd_t r2 = dd_select(dd_lt_d(length2, to_real(1e-20)), dd_from(to_real(1e-20)), length2);
      q = dd3_add_v3(dd3_scale(dd3_abs(q), dd_div_d_by(to_real(a), r2)), v);
      d = d * to_real(fabs(a)) / r2.hi;
      break;
    }
    case HYBRID_ABS_FOLD:
      q = dd3_add_v3(dd3_abs(q), v);
      break;
    default:
      break;
  }
  *z = dd3_select(live, q, *z);
  *dr = lane_select(live, d, *dr);
}

/* hybrid_estimate from an orbit that ended in pairs: r from the pairs (rounded to double it would
 * move the estimate in steps of an ulp of r over dr, coarse while dr is small), the box's
 * distance from |z_i| - 1 in pairs, where the subtraction cancels. */
inline real_t hybrid_estimate_dd(int estimate, dd3_t z, real_t dr) {
  const real_t safe_dr = fmax(fabs(dr), to_real(FR_SCALAR_MIN));
  if (estimate == HYBRID_ESTIMATE_BOX) return dd3_unit_box_distance(z) / safe_dr;
  const dd_t r = dd_sqrt(dd3_length2(z));
  if (estimate == HYBRID_ESTIMATE_LOG) {
    /* 0.5 r ln r to first order in r's low part */
    const real_t log_hi = log(fmax(r.hi, to_real(FR_SCALAR_EPSILON)));
    return to_real(0.5) * (log_hi * r.hi + (log_hi + to_real(1)) * r.lo) / safe_dr;
  }
  return r.hi / safe_dr + r.lo / safe_dr;
}
