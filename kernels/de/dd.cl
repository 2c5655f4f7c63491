/* fr/dd.cl — double-double arithmetic: a number as the unevaluated sum hi + lo of two doubles,
 * |lo| <= ulp(hi) / 2, about 106 bits (32 decimal digits) where a double has 53. For positions
 * past what double resolves: a view 1e-20 across at |p| ~ 1 (deep zoom, docs/deep_zoom.md).
 *
 * The building blocks are exact: TwoSum (Knuth, TAOCP vol. 2, 4.2.2: s + e = a + b exactly, with
 * s = fl(a + b)) and TwoProd through the fused multiply-add (p + e = a b exactly); the operations
 * on pairs follow Dekker (1971) and the QD library's algorithms (Hida, Li and Bailey, 2001). They
 * hold only when the compiler keeps every rounding: a kernel that uses this file is built without
 * -cl-fast-relaxed-math, -cl-unsafe-math-optimizations and -cl-mad-enable, which would let it
 * reassociate (a - (s - v)) to 0 and lose the error terms. render/dd_selftest.hpp checks a device
 * does keep them.
 *
 * Lane-generic like the rest of the library (prelude.cl): hi and lo are real_t, one pair per
 * lane, and a comparison gives mask_t. Double only (FR_DOUBLE 1). */
#if !FR_DOUBLE
#error "fr/dd.cl needs a double kernel (FR_DOUBLE 1)"
#endif

typedef struct {
  real_t hi, lo;
} dd_t;

typedef struct {
  dd_t x, y, z;
} dd3_t;

inline dd_t dd_make(real_t hi, real_t lo) {
  dd_t r;
  r.hi = hi;
  r.lo = lo;
  return r;
}

inline dd_t dd_from(real_t a) {
  return dd_make(a, (real_t)0);
}

/* Knuth's TwoSum: s = fl(a + b) and e with s + e = a + b exactly, for any a and b. */
inline dd_t dd_two_sum(real_t a, real_t b) {
  const real_t s = a + b;
  const real_t v = s - a;
  const real_t e = (a - (s - v)) + (b - v);
  return dd_make(s, e);
}

/* Dekker's FastTwoSum: the same when |a| >= |b| (or a is 0), in three operations. */
inline dd_t dd_quick_two_sum(real_t a, real_t b) {
  const real_t s = a + b;
  return dd_make(s, b - (s - a));
}

/* p = fl(a b) and e with p + e = a b exactly, through the fused multiply-add. */
inline dd_t dd_two_prod(real_t a, real_t b) {
  const real_t p = a * b;
  return dd_make(p, fma(a, b, -p));
}

inline real_t dd_to_real(dd_t a) {
  return a.hi + a.lo;
}

inline dd_t dd_neg(dd_t a) {
  return dd_make(-a.hi, -a.lo);
}

/* a + b with both error terms carried (QD's "IEEE" addition): relative error about 2^-106. */
inline dd_t dd_add(dd_t a, dd_t b) {
  dd_t s = dd_two_sum(a.hi, b.hi);
  const dd_t t = dd_two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = dd_quick_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return dd_quick_two_sum(s.hi, s.lo);
}

inline dd_t dd_add_d(dd_t a, real_t b) {
  dd_t s = dd_two_sum(a.hi, b);
  s.lo += a.lo;
  return dd_quick_two_sum(s.hi, s.lo);
}

inline dd_t dd_sub(dd_t a, dd_t b) {
  return dd_add(a, dd_neg(b));
}

inline dd_t dd_mul(dd_t a, dd_t b) {
  dd_t p = dd_two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return dd_quick_two_sum(p.hi, p.lo);
}

inline dd_t dd_mul_d(dd_t a, real_t b) {
  dd_t p = dd_two_prod(a.hi, b);
  p.lo += a.lo * b;
  return dd_quick_two_sum(p.hi, p.lo);
}

/* a / b by long division, three quotient digits (QD's accurate division). b.hi must not be 0. */
inline dd_t dd_div(dd_t a, dd_t b) {
  const real_t q1 = a.hi / b.hi;
  dd_t r = dd_sub(a, dd_mul_d(b, q1));
  const real_t q2 = r.hi / b.hi;
  r = dd_sub(r, dd_mul_d(b, q2));
  const real_t q3 = r.hi / b.hi;
  return dd_add_d(dd_quick_two_sum(q1, q2), q3);
}

/* a / b for a double a: two quotient digits (the second from the remainder a - q1 b, exact to
 * the pair's precision), which is as accurate as the pair: the first digit is within an ulp, so
 * the rest is a double's worth below it. b.hi must not be 0. */
inline dd_t dd_div_d_by(real_t a, dd_t b) {
  const real_t q1 = a / b.hi;
  const dd_t r = dd_sub(dd_from(a), dd_mul_d(b, q1));
  return dd_quick_two_sum(q1, r.hi / b.hi);
}

/* sqrt(a) for a >= 0 (0 for a <= 0): one Newton step from the double root (Karp and Markstein). */
inline dd_t dd_sqrt(dd_t a) {
  const mask_t positive = a.hi > (real_t)0;
  const real_t x = sqrt(fmax(a.hi, (real_t)0));
  const real_t safe = lane_select(positive, x, 1);
  const dd_t r = dd_sub(a, dd_two_prod(x, x));
  const dd_t root = dd_add_d(dd_from(x), r.hi * (real_t)0.5 / safe);
  return dd_make(lane_select(positive, root.hi, 0), lane_select(positive, root.lo, 0));
}

inline dd_t dd_select(mask_t m, dd_t if_true, dd_t if_false) {
  return dd_make(lane_select(m, if_true.hi, if_false.hi), lane_select(m, if_true.lo, if_false.lo));
}

/* Comparisons of normalised pairs: by hi, then by lo. */
inline mask_t dd_lt(dd_t a, dd_t b) {
  return (a.hi < b.hi) | ((a.hi == b.hi) & (a.lo < b.lo));
}

inline mask_t dd_lt_d(dd_t a, real_t b) {
  return (a.hi < b) | ((a.hi == b) & (a.lo < (real_t)0));
}

inline mask_t dd_gt_d(dd_t a, real_t b) {
  return (a.hi > b) | ((a.hi == b) & (a.lo > (real_t)0));
}

inline dd_t dd_abs(dd_t a) {
  return dd_select(dd_lt_d(a, (real_t)0), dd_neg(a), a);
}

/* ---- vectors of pairs ---- */

inline dd3_t dd3_make(dd_t x, dd_t y, dd_t z) {
  dd3_t r;
  r.x = x;
  r.y = y;
  r.z = z;
  return r;
}

inline dd3_t dd3_from(vec3_t v) {
  return dd3_make(dd_from(v.x), dd_from(v.y), dd_from(v.z));
}

inline vec3_t dd3_to_v3(dd3_t a) {
  return v3(dd_to_real(a.x), dd_to_real(a.y), dd_to_real(a.z));
}

inline dd3_t dd3_add(dd3_t a, dd3_t b) {
  return dd3_make(dd_add(a.x, b.x), dd_add(a.y, b.y), dd_add(a.z, b.z));
}

/* A position plus an offset known in double: a ray's origin plus t times its direction. */
inline dd3_t dd3_add_v3(dd3_t a, vec3_t b) {
  return dd3_make(dd_add_d(a.x, b.x), dd_add_d(a.y, b.y), dd_add_d(a.z, b.z));
}

inline dd3_t dd3_scale(dd3_t a, dd_t s) {
  return dd3_make(dd_mul(a.x, s), dd_mul(a.y, s), dd_mul(a.z, s));
}

inline dd3_t dd3_scale_d(dd3_t a, real_t s) {
  return dd3_make(dd_mul_d(a.x, s), dd_mul_d(a.y, s), dd_mul_d(a.z, s));
}

inline dd_t dd3_length2(dd3_t a) {
  return dd_add(dd_add(dd_mul(a.x, a.x), dd_mul(a.y, a.y)), dd_mul(a.z, a.z));
}

inline dd3_t dd3_select(mask_t m, dd3_t if_true, dd3_t if_false) {
  return dd3_make(dd_select(m, if_true.x, if_false.x), dd_select(m, if_true.y, if_false.y),
                  dd_select(m, if_true.z, if_false.z));
}
