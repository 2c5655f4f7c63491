/* fr/jerusalem.cl — the Jerusalem cube (Eric Baird, 2011).
 *
 * The cube [-1, 1]^3 is replaced by 8 corner cubes scaled by k = sqrt(2) - 1 and 12 edge cubes
 * scaled by k^2, centred on the edges between them (2k + k^2 = 1: corner, edge, corner fill an
 * edge exactly), and so on in each copy. By the cube's symmetry only two pieces matter once the
 * point is folded into x >= y >= z >= 0 (p_fold_menger): the corner cube at (1 - k)(1, 1, 1) and
 * the edge cube at (1 - k^2)(1, 1, 0) — each other piece is a mirror image of one of them on the
 * far side of a mirror, so never nearer. Each level descends into the nearer of the two, and
 * keeps the other one's box distance as a candidate: the result, the least of those candidates
 * and the last box's, is a lower bound of the distance to the level-n cube (each candidate bounds
 * the distance to the part inside its box). *trap receives the number of edge steps taken over
 * the iterations (0 to 1), for colouring. */
#include "fr/primitives.cl"
#include "fr/folds.cl"

real_t de_jerusalem_cube(vec3_t p, int iterations, real_t* trap) {
  const scalar_t k = (scalar_t)(1.4142135623730951 - 1);
  const scalar_t k2 = k * k;
  const vec3_t corner_centre = v3s(1 - k, 1 - k, 1 - k);
  const vec3_t edge_centre = v3s(1 - k2, 1 - k2, 0);
  vec3_t z = p;
  real_t size = to_real(1); /* the current copy's scale */
  real_t best = to_real(1e30); /* no candidate yet (finite: fast-math builds assume no infinities) */
  real_t edges = to_real(0);
  for (int i = 0; i < iterations; ++i) {
    z = p_fold_menger(z);
    real_t to_corner = sd_box(v3_sub(z, corner_centre), v3s(k, k, k));
    real_t to_edge = sd_box(v3_sub(z, edge_centre), v3s(k2, k2, k2));
    mask_t into_corner = to_corner <= to_edge;
    best = fmin(best, size * lane_select(into_corner, to_edge, to_corner));
    vec3_t in_corner = v3_scale(v3_sub(z, corner_centre), to_real(1 / k));
    vec3_t in_edge = v3_scale(v3_sub(z, edge_centre), to_real(1 / k2));
    z = v3_select(into_corner, in_corner, in_edge);
    size *= lane_select(into_corner, to_real(k), to_real(k2));
    edges += lane_select(into_corner, to_real(0), to_real(1));
  }
  *trap = edges / to_real(iterations > 0 ? iterations : 1);
  return fmin(best, size * sd_box(z, v3s(1, 1, 1)));
}
