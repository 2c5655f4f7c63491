/* fr/hypercomplex.cl — escape-time sets of four-dimensional number systems, sliced to 3D.
 *
 * - The cubic quaternion Julia set q <- q^3 + c (after Norton, SIGGRAPH 1982, and Hart, Sandin
 *   and Kauffman's DE, 1989): with q = (a, v), q^3 = (a^3 - 3 a |v|^2, (3 a^2 - |v|^2) v). The
 *   derivative's norm is bounded by 3 |q|^2 times the last one (each of the three terms of the
 *   product rule is), which the DE 0.5 |q| log |q| / |dq| uses.
 * - The Tetrabrot (Dominic Rochon, "A generalized Mandelbrot set for bicomplex numbers", Fractals
 *   8(4), 2000): the bicomplex Mandelbrot set, sliced at (x + i y) + (z + 0 i) j. In the
 *   idempotent basis a bicomplex number is a pair of complex numbers that iterate z <- z^2 + c
 *   each on its own: u = x + i (y - z) and w = x + i (y + z). So the set is {u in M and w in M},
 *   and a lower bound of its distance follows from lower bounds of each complex distance (see
 *   de_tetrabrot). */
#include "fr/operators.cl"

/* The cubic quaternion Julia set of c = (c_xyz, c_w), sliced at w = slice_w: the point p is the
 * quaternion x + y i + z j + slice_w k (x the real part, as in fr/julia.cl, so the slice holds the
 * real axis and shows the set's lobes rather than its rotational symmetry about c). *trap
 * receives min |q|^2 over the orbit. */
real_t de_quaternion_cubic_julia(vec3_t p, scalar_t slice_w, vec3_t c_xyz, scalar_t c_w,
                                 real_t bailout, int iterations, real_t* trap) {
  real_t a = p.x, x = p.y, y = p.z, z = to_real(slice_w); /* q = a + x i + y j + z k */
  real_t r2 = a * a + x * x + y * y + z * z;
  real_t dr = to_real(1);
  real_t orbit_min = r2;
  const real_t bailout2 = bailout * bailout;
  for (int i = 0; i < iterations; ++i) {
    const mask_t live = (r2 < bailout2) & (r2 > to_real(1e-8));
    if (!any_lane(live)) break;
    const real_t v2 = x * x + y * y + z * z;
    const real_t vector_factor = 3 * a * a - v2;
    const real_t na = a * (a * a - 3 * v2) + c_xyz.x;
    const real_t nx = vector_factor * x + c_xyz.y;
    const real_t ny = vector_factor * y + c_xyz.z;
    const real_t nz = vector_factor * z + to_real(c_w);
    dr = lane_select(live, 3 * r2 * dr, dr);
    a = lane_select(live, na, a);
    x = lane_select(live, nx, x);
    y = lane_select(live, ny, y);
    z = lane_select(live, nz, z);
    r2 = lane_select(live, a * a + x * x + y * y + z * z, r2);
    orbit_min = lane_select(live, fmin(orbit_min, r2), orbit_min);
  }
  *trap = orbit_min;
  const real_t r = sqrt(r2);
  return to_real(0.5) * r * log(fmax(r, to_real(FR_SCALAR_MIN))) / fmax(dr, to_real(FR_SCALAR_MIN));
}

/* A lower bound of the distance from c to the Mandelbrot set M (0 where the orbit did not
 * escape): Koebe's quarter theorem gives distance >= sinh(G) / (2 e^G |G'|) with the Green's
 * function G = log |z_n| / 2^n, so (1 - e^(-2G)) |z_n| 2^n / (4 |z_n'|), written here with
 * G 2^n = log |z_n|. The bailout is large (2^16) so that G is G's limit to float precision. */
inline real_t mandelbrot_distance_bound(real_t cx, real_t cy, int iterations, real_t* trap) {
  real_t zx = cx, zy = cy, dx = to_real(1), dy = to_real(0);
  real_t r2 = zx * zx + zy * zy;
  real_t orbit_min = r2;
  real_t two_n = to_real(1);
  mask_t live = r2 < to_real(65536.0 * 65536.0);
  for (int i = 0; i < iterations; ++i) {
    if (!any_lane(live)) break;
    /* z' <- 2 z z' + 1, then z <- z^2 + c. */
    const real_t ndx = 2 * (zx * dx - zy * dy) + to_real(1);
    const real_t ndy = 2 * (zx * dy + zy * dx);
    const real_t nzx = zx * zx - zy * zy + cx;
    const real_t nzy = 2 * zx * zy + cy;
    dx = lane_select(live, ndx, dx);
    dy = lane_select(live, ndy, dy);
    zx = lane_select(live, nzx, zx);
    zy = lane_select(live, nzy, zy);
    two_n = lane_select(live, 2 * two_n, two_n);
    r2 = lane_select(live, zx * zx + zy * zy, r2);
    orbit_min = lane_select(live, fmin(orbit_min, r2), orbit_min);
    live = live & (r2 < to_real(65536.0 * 65536.0));
  }
  *trap = orbit_min;
  const real_t r = sqrt(r2);
  const real_t log_r = log(fmax(r, to_real(1)));
  const real_t g = log_r / two_n;
  const real_t bound = -expm1(-2 * g) * r * two_n /
                       (4 * fmax(sqrt(dx * dx + dy * dy), to_real(FR_SCALAR_MIN)));
  return lane_select(r2 >= to_real(4), bound, to_real(0));
}

/* The Tetrabrot. The map (x, y, z) -> (u, w) stretches every length by sqrt(2) (|du|^2 + |dw|^2
 * = 2 (dx^2 + dy^2 + dz^2)), and the distance to M x M in C^2 is sqrt(d_u^2 + d_w^2): so
 * sqrt(b_u^2 + b_w^2) / sqrt(2), with b the lower bounds above, is a lower bound in 3D. *trap
 * receives the smaller of the two orbits' min |z|^2. */
real_t de_tetrabrot(vec3_t p, int iterations, real_t* trap) {
  real_t trap_u, trap_w;
  const real_t b_u = mandelbrot_distance_bound(p.x, p.y - p.z, iterations, &trap_u);
  const real_t b_w = mandelbrot_distance_bound(p.x, p.y + p.z, iterations, &trap_w);
  *trap = fmin(trap_u, trap_w);
  return sqrt(to_real(0.5) * (b_u * b_u + b_w * b_w));
}
