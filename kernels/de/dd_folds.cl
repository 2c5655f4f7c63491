/* fr/dd_folds.cl — the folds and rotations of fr/folds.cl and fr/operators.cl on points given in
 * double-double (fr/dd.cl), for the pair estimates of box-like and IFS formulas (fr/mandelbox_dd.cl,
 * fr/menger_dd.cl, fr/hybrid_dd.cl).
 *
 * Comparisons, negations, swaps and absolute values are exact on pairs; reflections across planes
 * with irrational normals and rotations round like one pair operation. Every constant (a plane's
 * normal, a rotation's cosine and sine) is the same double the double form uses, so where double
 * resolves a view the two forms agree to double's rounding. The folds a loop calls every iteration
 * are always inlined: a dd3_t is six vectors of doubles, which a call passes through memory. */
#include "fr/dd.cl"
#include "fr/kifs.cl" /* FR_PHI, and the double forms */

/* 2 clamp(x, -limit, limit) - x, exactly: 2 limit - x above the limit, -2 limit - x below it. */
inline dd_t dd_fold_box1(dd_t x, real_t limit) {
  const dd_t above = dd_add_d(dd_neg(x), 2 * limit);
  const dd_t below = dd_add_d(dd_neg(x), -2 * limit);
  return dd_select(dd_gt_d(x, limit), above, dd_select(dd_lt_d(x, -limit), below, x));
}

/* Lowe's box fold (p_fold_box). */
__attribute__((always_inline)) inline dd3_t dd3_fold_box(dd3_t z, real_t limit) {
  return dd3_make(dd_fold_box1(z.x, limit), dd_fold_box1(z.y, limit), dd_fold_box1(z.z, limit));
}

/* Lowe's sphere fold with its constants in pairs, worked out once per evaluation: the radii's
 * squares exact (a double's square is a pair; a factor rounded to double would make a shape 1e-16
 * off the parameters' own, which a view past double sees) and the inner factor fixed^2 / min^2.
 * They are the same in every lane, so scalars: nothing more for the loop to keep in vectors. */
typedef struct {
  scalar_t min2_hi, min2_lo, fixed2_hi, fixed2_lo, inner_hi, inner_lo;
} dd_sphere_fold_t;

inline dd_sphere_fold_t dd_sphere_fold_prepare(scalar_t min_radius, scalar_t fixed_radius) {
  dd_sphere_fold_t f;
  f.min2_hi = min_radius * min_radius;
  f.min2_lo = fma(min_radius, min_radius, -f.min2_hi); /* TwoProd's error term */
  f.fixed2_hi = fixed_radius * fixed_radius;
  f.fixed2_lo = fma(fixed_radius, fixed_radius, -f.fixed2_hi);
  /* fixed2 / min2 in two quotient digits, in scalars (dd_div's way): the remainder of the first
   * digit exact through TwoProd, the second from it. */
  const scalar_t q1 = f.fixed2_hi / f.min2_hi;
  const scalar_t product = q1 * f.min2_hi;
  const scalar_t product_error = fma(q1, f.min2_hi, -product);
  const scalar_t rest =
      ((f.fixed2_hi - product) - product_error) + f.fixed2_lo - q1 * f.min2_lo;
  const scalar_t q2 = rest / f.min2_hi;
  f.inner_hi = q1 + q2;
  f.inner_lo = q2 - (f.inner_hi - q1);
  return f;
}

/* a < b for a pair b given as scalars. */
inline mask_t dd_lt_s(dd_t a, scalar_t b_hi, scalar_t b_lo) {
  return (a.hi < b_hi) | ((a.hi == b_hi) & (a.lo < b_lo));
}

/* The fold's factor at a folded point whose |.|^2 is f2 (p_fold_sphere's): fixed^2 / min^2
 * inside min_radius, fixed^2 / f2 between the radii, 1 outside. */
__attribute__((always_inline)) inline dd_t dd_sphere_fold_factor(dd_t f2,
                                                                  const dd_sphere_fold_t* fold) {
  const mask_t inner = dd_lt_s(f2, fold->min2_hi, fold->min2_lo);
  const mask_t shell = !inner & dd_lt_s(f2, fold->fixed2_hi, fold->fixed2_lo);
  const dd_t safe_r2 = dd_select(shell, f2, dd_from(to_real(1)));
  /* A square without a low part (fixed radius 1, 0.5): a double over the pair, the cheaper way. */
  const dd_t between =
      fold->fixed2_lo == 0
          ? dd_div_d_by(to_real(fold->fixed2_hi), safe_r2)
          : dd_div(dd_make(to_real(fold->fixed2_hi), to_real(fold->fixed2_lo)), safe_r2);
  return dd_select(inner, dd_make(to_real(fold->inner_hi), to_real(fold->inner_lo)),
                   dd_select(shell, between, dd_from(to_real(1))));
}

/* The distance from z (in pairs) to the unit box |x_i| <= 1 (sd_box's formula), with each
 * |z_i| - 1 taken in pairs, where the subtraction cancels near a face, and the rest in double. */
inline real_t dd3_unit_box_distance(dd3_t z) {
  const vec3_t q = v3(dd_to_real(dd_add_d(dd_abs(z.x), to_real(-1))),
                      dd_to_real(dd_add_d(dd_abs(z.y), to_real(-1))),
                      dd_to_real(dd_add_d(dd_abs(z.z), to_real(-1))));
  const real_t outside = v3_length(v3_max(q, v3s(0, 0, 0)));
  const real_t inside = fmin(fmax(q.x, fmax(q.y, q.z)), to_real(0));
  return outside + inside;
}

inline dd3_t dd3_abs(dd3_t z) { return dd3_make(dd_abs(z.x), dd_abs(z.y), dd_abs(z.z)); }

/* The pair with the larger value first. */
inline void dd_order(dd_t* a, dd_t* b) {
  const mask_t swap = dd_lt(*a, *b);
  const dd_t first = dd_select(swap, *b, *a), second = dd_select(swap, *a, *b);
  *a = first;
  *b = second;
}

/* Menger's fold (p_fold_menger): the positive octant, then x >= y >= z. */
inline dd3_t dd3_fold_menger(dd3_t z) {
  dd3_t q = dd3_abs(z);
  dd_order(&q.x, &q.y);
  dd_order(&q.x, &q.z);
  dd_order(&q.y, &q.z);
  return q;
}

/* (a, b) <- (-b, -a) where a + b < 0: one of p_fold_sierpinski's reflections. */
inline void dd_reflect_pair(dd_t* a, dd_t* b) {
  const mask_t m = dd_lt_d(dd_add(*a, *b), to_real(0));
  const dd_t first = dd_select(m, dd_neg(*b), *a), second = dd_select(m, dd_neg(*a), *b);
  *a = first;
  *b = second;
}

/* Sierpinski's fold (p_fold_sierpinski). */
inline dd3_t dd3_fold_sierpinski(dd3_t z) {
  dd3_t q = z;
  dd_reflect_pair(&q.x, &q.y);
  dd_reflect_pair(&q.x, &q.z);
  dd_reflect_pair(&q.y, &q.z);
  return q;
}

inline dd_t dd3_dot_v3(dd3_t z, vec3_t n) {
  return dd_add(dd_add(dd_mul_d(z.x, n.x), dd_mul_d(z.y, n.y)), dd_mul_d(z.z, n.z));
}

/* The reflection across the plane through the origin with unit normal n, for points on its
 * negative side (p_fold_plane with d = 0). */
inline dd3_t dd3_fold_plane(dd3_t z, vec3_t n) {
  const dd_t side = dd3_dot_v3(z, n);
  const dd_t twice = dd_mul_d(side, to_real(-2));
  const dd3_t reflected = dd3_make(dd_add(z.x, dd_mul_d(twice, n.x)),
                                   dd_add(z.y, dd_mul_d(twice, n.y)),
                                   dd_add(z.z, dd_mul_d(twice, n.z)));
  return dd3_select(dd_lt_d(side, to_real(0)), reflected, z);
}

/* The icosahedral fold of fr/kifs.cl (p_fold_icosahedral), with its normals. */
inline dd3_t dd3_fold_icosahedral(dd3_t z) {
  const vec3_t n_a = v3s(-FR_PHI / 2, -0.5, 0.5 / FR_PHI);
  const vec3_t n_b = v3s(FR_PHI / 2, -0.5, 0.5 / FR_PHI);
  for (int round = 0; round < 3; ++round) {
    z = dd3_abs(z);
    z = dd3_fold_plane(z, n_a);
    z = dd3_fold_plane(z, n_b);
  }
  return z;
}

/* p_rotate_x, p_rotate_y and p_rotate_z with their cosine c and sine s given. */
inline dd3_t dd3_rotate_x_cs(dd3_t q, real_t c, real_t s) {
  return dd3_make(q.x, dd_add(dd_mul_d(q.y, c), dd_mul_d(q.z, s)),
                  dd_add(dd_mul_d(q.y, -s), dd_mul_d(q.z, c)));
}
inline dd3_t dd3_rotate_y_cs(dd3_t q, real_t c, real_t s) {
  return dd3_make(dd_add(dd_mul_d(q.x, c), dd_mul_d(q.z, -s)), q.y,
                  dd_add(dd_mul_d(q.x, s), dd_mul_d(q.z, c)));
}
inline dd3_t dd3_rotate_z_cs(dd3_t q, real_t c, real_t s) {
  return dd3_make(dd_add(dd_mul_d(q.x, c), dd_mul_d(q.y, s)),
                  dd_add(dd_mul_d(q.x, -s), dd_mul_d(q.y, c)), q.z);
}

/* p_rotate_xyz: Euler angles in radians, x then y then z; zero angles cost nothing. */
__attribute__((always_inline)) inline dd3_t dd3_rotate_xyz(dd3_t q, scalar_t angle_x, scalar_t angle_y, scalar_t angle_z) {
  if (angle_x != 0) q = dd3_rotate_x_cs(q, (real_t)cos(angle_x), (real_t)sin(angle_x));
  if (angle_y != 0) q = dd3_rotate_y_cs(q, (real_t)cos(angle_y), (real_t)sin(angle_y));
  if (angle_z != 0) q = dd3_rotate_z_cs(q, (real_t)cos(angle_z), (real_t)sin(angle_z));
  return q;
}
