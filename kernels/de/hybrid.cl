/* fr/hybrid.cl — formula steps for hybrids: a sequence of steps applied each iteration, each one
 * of the kinds below with its own parameters (a, b, v), as Mandelbulber's hybrid formulas chain
 * whole formulas. The step's kind is meant to be compiled in (a FR_PARAM_SPECIALIZE choice), so
 * the switch folds away and an unused kind costs nothing.
 *
 * Every step updates z and the running derivative dr (the factor by which it can stretch lengths,
 * first order): folds and rotations leave dr alone, scalings multiply it, steps that add the
 * starting point p add 1. The estimate at the end is chosen by the scene: 0.5 r ln r / dr for
 * polynomial-like (bulb, quaternion) escape, r / dr for linear (box-like) escape, or the unit
 * box's distance / dr for Menger-like IFS. A hybrid's estimate is first order, not a proof: the
 * hybrid scene multiplies it by a safety factor that `fractalis check` confirms. */
#include "fr/folds.cl"
#include "fr/operators.cl"
#include "fr/primitives.cl"
#include "fr/mandelbulb.cl"
#include "fr/kifs.cl"

#define HYBRID_NONE 0
#define HYBRID_BULB 1             /* z <- z^a + p (White and Nylander's triplex power) */
#define HYBRID_BOX_FOLD 2         /* Lowe's box fold to +-a */
#define HYBRID_SPHERE_FOLD 3      /* Lowe's sphere fold, min radius a, fixed radius b */
#define HYBRID_SCALE_TRANSLATE 4  /* z <- a z + v + p (the Mandelbox's scale and add) */
#define HYBRID_MENGER 5           /* Menger's fold and scale about v (Knighty) */
#define HYBRID_OCTAHEDRAL 6       /* KIFS: octahedral fold, z <- a z - v (a - 1) */
#define HYBRID_ICOSAHEDRAL 7      /* KIFS: icosahedral fold, likewise */
#define HYBRID_TETRAHEDRAL 8      /* KIFS: tetrahedral fold, likewise */
#define HYBRID_ROTATE 9           /* rotation by the Euler angles v, degrees */
#define HYBRID_QUATERNION_SQUARE 10 /* z <- z^2 + p as the quaternion x + y i + z j squared */
#define HYBRID_KALI 11            /* Kali's abs-invert: z <- a |z| / |z|^2 + v */
#define HYBRID_ABS_FOLD 12        /* z <- |z| + v, coordinate by coordinate */
#define HYBRID_KIND_COUNT 13

/* The final estimate's forms. */
#define HYBRID_ESTIMATE_LOG 0
#define HYBRID_ESTIMATE_LINEAR 1
#define HYBRID_ESTIMATE_BOX 2

/* p_rotate_xyz with the angles as lane values (a vec3 parameter arrives as one). */
inline vec3_t hybrid_rotate(vec3_t q, vec3_t angles) {
  real_t c = cos(angles.x), s = sin(angles.x);
  q = v3(q.x, c * q.y + s * q.z, -s * q.y + c * q.z);
  c = cos(angles.y);
  s = sin(angles.y);
  q = v3(c * q.x - s * q.z, q.y, s * q.x + c * q.z);
  c = cos(angles.z);
  s = sin(angles.z);
  return v3(c * q.x + s * q.y, -s * q.x + c * q.y, q.z);
}

/* One step of kind `kind` on the lanes in `live`. */
inline void hybrid_step(int kind, mask_t live, vec3_t* z, real_t* dr, vec3_t p, scalar_t a,
                        scalar_t b, vec3_t v) {
  vec3_t q = *z;
  real_t d = *dr;
  switch (kind) {
    case HYBRID_BULB: {
      const real_t r = v3_length(q);
      real_t r_pow;
      const int n = (int)a;
      q = (a == (scalar_t)n && n >= 1 && n <= 64) ? mandelbulb_pow_int(q, r, n, &r_pow)
                                                 : mandelbulb_pow_real(q, r, to_real(a), &r_pow);
      q = v3_add(q, p);
      d = to_real(a) * r_pow * d + to_real(1);
      break;
    }
    case HYBRID_BOX_FOLD:
      q = p_fold_box(q, to_real(a));
      break;
    case HYBRID_SPHERE_FOLD:
      q = p_fold_sphere(q, to_real(a), to_real(b), &d);
      break;
    case HYBRID_SCALE_TRANSLATE:
      q = v3_add(v3_add(v3_scale(q, to_real(a)), v), p);
      d = d * to_real(fabs(a)) + to_real(1);
      break;
    case HYBRID_MENGER: {
      const real_t step = to_real(a - 1);
      q = p_fold_menger(q);
      q.x = to_real(a) * q.x - v.x * step;
      q.y = to_real(a) * q.y - v.y * step;
      q.z = to_real(a) * q.z;
      q.z = lane_select(q.z > to_real(0.5) * v.z * step, q.z - v.z * step, q.z);
      d = d * to_real(fabs(a));
      break;
    }
    case HYBRID_OCTAHEDRAL:
    case HYBRID_ICOSAHEDRAL:
    case HYBRID_TETRAHEDRAL:
      q = kind == HYBRID_OCTAHEDRAL    ? p_fold_menger(q)
          : kind == HYBRID_ICOSAHEDRAL ? p_fold_icosahedral(q)
                                       : p_fold_sierpinski(q);
      q = v3_sub(v3_scale(q, to_real(a)), v3_scale(v, to_real(a - 1)));
      d = d * to_real(fabs(a));
      break;
    case HYBRID_ROTATE:
      q = hybrid_rotate(q, v3_scale(v, to_real(M_PI / 180)));
      break;
    case HYBRID_QUATERNION_SQUARE: {
      const real_t r = v3_length(q);
      q = v3(q.x * q.x - q.y * q.y - q.z * q.z + p.x, 2 * q.x * q.y + p.y, 2 * q.x * q.z + p.z);
      d = 2 * r * d + to_real(1);
      break;
    }
    case HYBRID_KALI: {
      const real_t r2 = fmax(v3_length2(q), to_real(1e-20));
      q = v3_add(v3_scale(v3_abs(q), to_real(a) / r2), v);
      d = d * to_real(fabs(a)) / r2;
      break;
    }
    case HYBRID_ABS_FOLD:
      q = v3_add(v3_abs(q), v);
      break;
    default:
      break;
  }
  *z = v3_select(live, q, *z);
  *dr = lane_select(live, d, *dr);
}

/* The estimate from the last z and dr. */
inline real_t hybrid_estimate(int estimate, vec3_t z, real_t dr) {
  const real_t r = v3_length(z);
  const real_t safe_dr = fmax(fabs(dr), to_real(FR_SCALAR_MIN));
  if (estimate == HYBRID_ESTIMATE_LOG)
    return to_real(0.5) * r * log(fmax(r, to_real(FR_SCALAR_EPSILON))) / safe_dr;
  if (estimate == HYBRID_ESTIMATE_BOX) return sd_box(z, v3s(1, 1, 1)) / safe_dr;
  return r / safe_dr;
}
