/* fr/menger.cl — the Menger sponge by folding (after Knighty).
 *
 * Each iteration folds into the fundamental domain x >= y >= z >= 0, optionally rotates, and
 * scales about the corner `offset`; the middle layer (z beyond half the offset step) is shifted
 * back. With scale 3, offset (1,1,1) and no rotation, the zero set after n iterations is exactly
 * the level-n sponge (20^n cubes) inside [-1, 1]^3, and since folds are 1-Lipschitz the result is
 * a lower bound of the distance to it. *trap receives min |z|^2 over the orbit. */
#include "fr/primitives.cl"
#include "fr/operators.cl"
#include "fr/folds.cl"

/* One iteration: the fold, the rotation about x, the scaling about the corner, the middle layer
 * shifted back. (fr/menger_dd.cl runs it after its iterations in pairs.) */
inline vec3_t menger_step(vec3_t z, scalar_t scale, vec3_t offset, scalar_t rotation) {
  const real_t step = to_real(scale - 1);
  z = p_fold_menger(z);
  if (rotation != 0) z = p_rotate_x(z, rotation);
  z.x = to_real(scale) * z.x - offset.x * step;
  z.y = to_real(scale) * z.y - offset.y * step;
  z.z = to_real(scale) * z.z;
  z.z = lane_select(z.z > to_real(0.5) * offset.z * step, z.z - offset.z * step, z.z);
  return z;
}

real_t de_menger(vec3_t p, int iterations, scalar_t scale, vec3_t offset, scalar_t rotation,
                 real_t* trap) {
  vec3_t z = p;
  real_t orbit_min = v3_length2(z);
  for (int i = 0; i < iterations; ++i) {
    z = menger_step(z, scale, offset, rotation);
    orbit_min = fmin(orbit_min, v3_length2(z));
  }
  *trap = orbit_min;
  return sd_box(z, v3s(1, 1, 1)) * to_real(pown_scalar(1 / scale, iterations));
}

/* Smooth folds (after Darkbeam's smooth Menger, fractalforums.com, 2012): |x| becomes
 * sqrt(x^2 + s), and each compare-and-swap of the sort becomes its smooth blend, so the sponge's
 * edges round off with `smoothness` s. Both maps are 1-Lipschitz (the blend's Jacobian has
 * eigenvalues 1 and 1 - 2 f', f' in [0, 1]), so one step is scale-Lipschitz and box(z) / scale^n
 * stays a lower bound of the distance. */
inline void smooth_order(real_t* a, real_t* b, real_t s) {
  const real_t d = *a - *b;
  const real_t t = to_real(0.5) * (d - sqrt(d * d + s));
  *a -= t;
  *b += t;
}

real_t de_menger_smooth(vec3_t p, int iterations, scalar_t scale, vec3_t offset,
                        scalar_t smoothness, real_t* trap) {
  vec3_t z = p;
  real_t orbit_min = v3_length2(z);
  const real_t s = to_real(smoothness);
  const real_t step = to_real(scale - 1);
  for (int i = 0; i < iterations; ++i) {
    z = v3(sqrt(z.x * z.x + s), sqrt(z.y * z.y + s), sqrt(z.z * z.z + s));
    smooth_order(&z.x, &z.y, s);
    smooth_order(&z.x, &z.z, s);
    smooth_order(&z.y, &z.z, s);
    z.x = to_real(scale) * z.x - offset.x * step;
    z.y = to_real(scale) * z.y - offset.y * step;
    /* Menger's choice for the last coordinate, c - |z - c| (the sign is undone by the next fold
     * and by the box's symmetry), smoothed likewise. */
    const real_t c = to_real(0.5) * offset.z * step;
    const real_t zz = to_real(scale) * z.z - c;
    z.z = c - sqrt(zz * zz + s);
    orbit_min = fmin(orbit_min, v3_length2(z));
  }
  *trap = orbit_min;
  return sd_box(z, v3s(1, 1, 1)) * to_real(pown_scalar(1 / scale, iterations));
}

/* The Menger sponge's four-dimensional sibling, sliced at w = slice_w: in a hypercube split 3^4
 * ways, the cells with at most one middle coordinate are kept (the 3D sponge's rule), by the same
 * folds: |.| on four coordinates, a sort into x >= y >= z >= w, the three largest scaled towards
 * their corner and the smallest given Menger's choice. Distances in 4D bound those in any slice,
 * so box4(z) / scale^n is a lower bound. The slice w = 0 is Cantor's dust (all of x, y, z outer);
 * others cut its tunnels into lattices. */
inline void sort_pair(real_t* a, real_t* b) {
  const real_t hi = fmax(*a, *b), lo = fmin(*a, *b);
  *a = hi;
  *b = lo;
}

real_t de_menger_4d(vec3_t p, scalar_t slice_w, int iterations, scalar_t scale, real_t* trap) {
  real_t x = p.x, y = p.y, z = p.z, w = to_real(slice_w);
  real_t orbit_min = x * x + y * y + z * z + w * w;
  const real_t step = to_real(scale - 1);
  for (int i = 0; i < iterations; ++i) {
    x = fabs(x);
    y = fabs(y);
    z = fabs(z);
    w = fabs(w);
    sort_pair(&x, &y);
    sort_pair(&z, &w);
    sort_pair(&x, &z);
    sort_pair(&y, &w);
    sort_pair(&y, &z);
    x = to_real(scale) * x - step;
    y = to_real(scale) * y - step;
    z = to_real(scale) * z - step;
    const real_t c = to_real(0.5) * step;
    w = c - fabs(to_real(scale) * w - c);
    orbit_min = fmin(orbit_min, x * x + y * y + z * z + w * w);
  }
  *trap = orbit_min;
  const real_t ox = fmax(fabs(x) - 1, to_real(0)), oy = fmax(fabs(y) - 1, to_real(0));
  const real_t oz = fmax(fabs(z) - 1, to_real(0)), ow = fmax(fabs(w) - 1, to_real(0));
  const real_t inside = fmin(fmax(fmax(fabs(x), fabs(y)), fmax(fabs(z), fabs(w))) - 1, to_real(0));
  return (sqrt(ox * ox + oy * oy + oz * oz + ow * ow) + inside) *
         to_real(pown_scalar(1 / scale, iterations));
}
