/* fr/cantor.cl — Cantor's dust in 3D (Georg Cantor, 1883, the middle-thirds set; its cube
 * product): a cube replaced by its eight corner cubes, each 1/scale of its size, recursively.
 *
 * One step maps the positive octant's corner cube onto the whole, z <- scale |z| - (scale - 1),
 * coordinate by coordinate. For a point in the positive octant the positive corner cube is the
 * nearest of the eight (they are mirror images of one another across the coordinate planes, and
 * reflecting towards the point's side never increases a distance), so after n steps
 * box(z) / scale^n is the exact distance to the n-th level's cubes, a lower bound of the distance
 * to the dust inside them. Exact for every scale > 1 (below 2 the cubes overlap). */
#include "fr/primitives.cl"

real_t de_cantor_dust(vec3_t p, int iterations, scalar_t scale, real_t* trap) {
  vec3_t z = p;
  real_t orbit_min = v3_length2(z);
  const real_t step = to_real(scale - 1);
  for (int i = 0; i < iterations; ++i) {
    z = v3_sub(v3_scale(v3_abs(z), to_real(scale)), v3(step, step, step));
    orbit_min = fmin(orbit_min, v3_length2(z));
  }
  *trap = orbit_min;
  return sd_box(z, v3s(1, 1, 1)) * to_real(pown_scalar(1 / scale, iterations));
}
