/* fr/kifs.cl — Knighty's kaleidoscopic IFS (fractalforums.com, "Kaleidoscopic (escape time)
 * IFS", 2010) on the octahedron, the icosahedron, the dodecahedron and the tetrahedron.
 *
 * Each iteration folds the point into one chamber of the polyhedron's reflection group, rotates
 * it (Euler angles in radians about x, then y, then z) and scales it about the offset point:
 * z <- scale R fold(z) - offset (scale - 1). That map g is scale-Lipschitz (folds and rotations
 * are isometries or 1-Lipschitz), and g^-1 of the ball |z| <= |offset| lies inside that ball, so
 * the sets K_n = {p : |g^n(p)| <= |offset|} are nested and
 *     DE_n(p) = (|g^n(p)| - |offset|) scale^-n
 * is a lower bound of the distance to K_n, and so to the fractal K_n tends to, for any offset,
 * rotation and scale > 1. A lane whose |z| passes the bailout stops there (DE_k with k < n is a
 * lower bound too, the K_k being nested). *trap receives min |z|^2 over the orbit.
 *
 * The folds: the octahedral group's chamber is x >= y >= z >= 0 (p_fold_menger); the
 * icosahedral group (order 120, which the dodecahedron shares) is reached by three rounds of
 * the octant fold and two reflections, across the mirrors with unit normals
 * (-+phi/2, -1/2, 1/(2 phi)) — a fixed sequence that lands every point in the chamber around the
 * z axis bounded by x = 0 (checked over 10^5 random points when it was derived, and in
 * tests/de_library_test.cpp). That chamber holds the icosahedron's vertex direction
 * (0, 1, phi) and the dodecahedron's (0, 1/phi, phi): the default offsets. */
#include "fr/operators.cl"
#include "fr/folds.cl"

#define FR_PHI 1.6180339887498949

/* The icosahedral group's fold (see above): the point's image in the chamber around +z. */
inline vec3_t p_fold_icosahedral(vec3_t p) {
  const vec3_t n_a = v3s(-FR_PHI / 2, -0.5, 0.5 / FR_PHI);
  const vec3_t n_b = v3s(FR_PHI / 2, -0.5, 0.5 / FR_PHI);
  vec3_t z = p;
  for (int round = 0; round < 3; ++round) {
    z = v3_abs(z);
    z = p_fold_plane(z, n_a, 0);
    z = p_fold_plane(z, n_b, 0);
  }
  return z;
}

/* The KIFS iteration with the group's fold chosen by `group`: 0 octahedral, 1 icosahedral,
 * 2 tetrahedral (p_fold_sierpinski: the chamber around (1, 1, 1)). */
inline real_t kifs_iterate(vec3_t p, int group, int iterations, scalar_t scale, vec3_t offset,
                           scalar_t angle_x, scalar_t angle_y, scalar_t angle_z, real_t* trap) {
  vec3_t z = p;
  real_t r2 = v3_length2(z);
  real_t orbit_min = r2;
  real_t shrink = to_real(1);
  const real_t step = to_real(scale - 1);
  const real_t offset_length = v3_length(offset);
  const real_t bailout2 = to_real(1e8) * fmax(offset_length * offset_length, to_real(1));
  for (int i = 0; i < iterations; ++i) {
    mask_t live = r2 < bailout2;
    if (!any_lane(live)) break;
    vec3_t q = group == 0 ? p_fold_menger(z)
               : (group == 1 ? p_fold_icosahedral(z) : p_fold_sierpinski(z));
    q = p_rotate_xyz(q, angle_x, angle_y, angle_z);
    q = v3_sub(v3_scale(q, to_real(scale)), v3_scale(offset, step));
    z = v3_select(live, q, z);
    shrink = lane_select(live, shrink / to_real(scale), shrink);
    r2 = lane_select(live, v3_length2(z), r2);
    orbit_min = lane_select(live, fmin(orbit_min, r2), orbit_min);
  }
  *trap = orbit_min;
  return (sqrt(r2) - offset_length) * shrink;
}

/* Offset (1, 0, 0), an octahedron's vertex: Sierpinski's octahedron at scale 2. */
real_t de_kifs_octahedron(vec3_t p, int iterations, scalar_t scale, vec3_t offset,
                          scalar_t angle_x, scalar_t angle_y, scalar_t angle_z, real_t* trap) {
  return kifs_iterate(p, 0, iterations, scale, offset, angle_x, angle_y, angle_z, trap);
}

/* Offset along (0, 1, phi), an icosahedron's vertex. */
real_t de_kifs_icosahedron(vec3_t p, int iterations, scalar_t scale, vec3_t offset,
                           scalar_t angle_x, scalar_t angle_y, scalar_t angle_z, real_t* trap) {
  return kifs_iterate(p, 1, iterations, scale, offset, angle_x, angle_y, angle_z, trap);
}

/* Offset along (0, 1/phi, phi), a dodecahedron's vertex: the same group as the icosahedron's,
 * scaled about the other polyhedron's corner. */
real_t de_kifs_dodecahedron(vec3_t p, int iterations, scalar_t scale, vec3_t offset,
                            scalar_t angle_x, scalar_t angle_y, scalar_t angle_z, real_t* trap) {
  return kifs_iterate(p, 1, iterations, scale, offset, angle_x, angle_y, angle_z, trap);
}

/* Offset (1, 1, 1), a tetrahedron's vertex: Sierpinski's tetrahedron at scale 2, and with
 * rotations Knighty's twisted tetrahedral KIFS. */
real_t de_kifs_tetrahedron(vec3_t p, int iterations, scalar_t scale, vec3_t offset,
                           scalar_t angle_x, scalar_t angle_y, scalar_t angle_z, real_t* trap) {
  return kifs_iterate(p, 2, iterations, scale, offset, angle_x, angle_y, angle_z, trap);
}
