/* fr/sierpinski.cl — the Sierpinski tetrahedron by folding.
 *
 * Each iteration reflects the point towards the vertex (1, 1, 1) (fr/folds.cl) and scales about
 * `offset` by `scale`. With scale 2 and offset (1,1,1) the zero set after n iterations is exactly
 * the union of the 4^n level-n tetrahedra of the one with vertices (1,1,1), (1,-1,-1), (-1,1,-1),
 * (-1,-1,1); the result is a lower bound (de_tetrahedron is one, and the folds are reflections
 * of a set symmetric under them). *trap receives min |z|^2 over the orbit. */
#include "fr/primitives.cl"
#include "fr/folds.cl"

real_t de_sierpinski(vec3_t p, int iterations, scalar_t scale, vec3_t offset, real_t* trap) {
  vec3_t z = p;
  real_t orbit_min = v3_length2(z);
  const real_t step = to_real(scale - 1);
  for (int i = 0; i < iterations; ++i) {
    z = p_fold_sierpinski(z);
    z = v3_sub(v3_scale(z, to_real(scale)), v3_scale(offset, step));
    orbit_min = fmin(orbit_min, v3_length2(z));
  }
  *trap = orbit_min;
  return de_tetrahedron(z, to_real(1)) * to_real(pown_scalar(1 / scale, iterations));
}
