/* fr/powers.cl — whole powers without pow or trigonometry: x^n by repeated squaring, and a unit
 * complex number (cos a, sin a) raised to (cos n a, sin n a) by de Moivre's formula, also by
 * repeated squaring. The Mandelbulb (fr/mandelbulb.cl) and Mandelbulber2's bulb
 * (fr/mandelbulber.cl) take their whole powers so. */

/* x^n for a whole n >= 0 by repeated squaring; n is the same in every lane. Not OpenCL's pown:
 * with PoCL 3.1's pown a 640x360 Mandelbulb frame took 25.4 ms instead of 9.7 ms. */
inline real_t pow_int(real_t x, int n) {
  if (n <= 0) return to_real(1);
  /* The lowest set bit starts the product (no multiplication by 1), and x is squared only while
   * higher bits remain (no squaring after the last): x^7 in 4 multiplications, not 6. */
  while (!(n & 1)) {
    x *= x;
    n >>= 1;
  }
  real_t result = x;
  for (n >>= 1; n > 0; n >>= 1) {
    x *= x;
    if (n & 1) result *= x;
  }
  return result;
}

/* (c + i s)^n for a whole n >= 1, in place: rotates the unit vector (c, s) to n times its angle. */
inline void unit_complex_pow_int(real_t* c, real_t* s, int n) {
  if (n <= 0) {
    *c = to_real(1);
    *s = to_real(0);
    return;
  }
  /* As pow_int: the lowest set bit starts the product, and no squaring follows the last bit
   * (for n = 8, three squarings and no multiplication). */
  real_t base_c = *c;
  real_t base_s = *s;
  while (!(n & 1)) {
    real_t square_c = base_c * base_c - base_s * base_s;
    base_s = to_real(2) * base_c * base_s;
    base_c = square_c;
    n >>= 1;
  }
  real_t result_c = base_c;
  real_t result_s = base_s;
  for (n >>= 1; n > 0; n >>= 1) {
    real_t square_c = base_c * base_c - base_s * base_s;
    base_s = to_real(2) * base_c * base_s;
    base_c = square_c;
    if (n & 1) {
      real_t next_c = result_c * base_c - result_s * base_s;
      result_s = result_c * base_s + result_s * base_c;
      result_c = next_c;
    }
  }
  *c = result_c;
  *s = result_s;
}
