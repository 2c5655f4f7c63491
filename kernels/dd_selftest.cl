/* dd_selftest.cl — does this device keep double-double arithmetic's error terms (fr/dd.cl)?
 * For each pair (a, b): TwoSum's (s, e) and TwoProd's (p, e), which the host checks are exact
 * (render/dd_selftest.hpp). One pair a work-item, lanes 1. */
__kernel void fr_dd_selftest(__global const double* pairs, __global double* out, int count) {
  const int i = get_global_id(0);
  if (i >= count) return;
  const dd_t sum = dd_two_sum(pairs[2 * i], pairs[2 * i + 1]);
  const dd_t product = dd_two_prod(pairs[2 * i], pairs[2 * i + 1]);
  out[4 * i] = sum.hi;
  out[4 * i + 1] = sum.lo;
  out[4 * i + 2] = product.hi;
  out[4 * i + 3] = product.lo;
}
