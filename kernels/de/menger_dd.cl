/* fr/menger_dd.cl — the Menger sponge by folding (fr/menger.cl, after Knighty) at a point given
 * in double-double (fr/dd.cl), for views past what double resolves.
 *
 * The same iteration: fold into x >= y >= z >= 0, rotate about x, scale about the corner
 * `offset`, shift the middle layer back; the estimate is the box's distance over scale^n. A
 * rounding of z at iteration i moves the estimate's point by that rounding over scale^i, so once
 * scale^i x pixel exceeds 1000 ulps of |z| the rest runs in double (a lane switches once; the loop
 * keeps the pairs until every lane may switch). `pixel` 0 keeps every iteration in pairs. The
 * rotation's cosine and sine are doubles, the same as the double form's. */
#include "fr/dd.cl"
#include "fr/primitives.cl"
#include "fr/operators.cl"
#include "fr/folds.cl"
#include "fr/menger.cl"
#include "fr/dd_folds.cl"

real_t de_menger_dd(dd3_t p, int iterations, scalar_t scale, vec3_t offset, scalar_t rotation,
                    real_t pixel) {
  const real_t step = to_real(scale - 1);
  const real_t c = (real_t)cos(rotation), s = (real_t)sin(rotation);
  const real_t switch_ulps = to_real(1000 * DBL_EPSILON);
  dd3_t z = p;
  real_t dr = to_real(1); /* scale^i */
  int i = 0;
  for (; i < iterations; ++i) {
    const real_t size = sqrt(fmax(dd_to_real(dd3_length2(z)), (real_t)0));
    if (!any_lane(dr * pixel <= switch_ulps * fmax(size, (real_t)1))) break;
    dd_t x = dd_abs(z.x), y = dd_abs(z.y), w = dd_abs(z.z);
    dd_order(&x, &y);
    dd_order(&x, &w);
    dd_order(&y, &w);
    if (rotation != 0) {
      const dd_t ry = dd_add(dd_mul_d(y, c), dd_mul_d(w, s));
      const dd_t rw = dd_add(dd_mul_d(y, -s), dd_mul_d(w, c));
      y = ry;
      w = rw;
    }
    x = dd_add_d(dd_mul_d(x, to_real(scale)), -offset.x * step);
    y = dd_add_d(dd_mul_d(y, to_real(scale)), -offset.y * step);
    w = dd_mul_d(w, to_real(scale));
    w = dd_select(dd_gt_d(w, to_real(0.5) * offset.z * step), dd_add_d(w, -offset.z * step), w);
    z = dd3_make(x, y, w);
    dr *= to_real(scale);
  }
  if (i == iterations) {
    /* Every level in pairs (a point this close to a level-n sponge's face): the box's distance
     * from the pairs, where |z| - 1 cancels. */
    return dd3_unit_box_distance(z) * to_real(pown_scalar(1 / scale, iterations));
  }
  /* The rest in double, as fr/menger.cl's loop. */
  vec3_t zd = dd3_to_v3(z);
  for (; i < iterations; ++i) zd = menger_step(zd, scale, offset, rotation);
  return sd_box(zd, v3s(1, 1, 1)) * to_real(pown_scalar(1 / scale, iterations));
}
