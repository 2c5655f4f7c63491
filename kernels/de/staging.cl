/* fr/staging.cl — helpers for composed scenes (the showcases): fractals placed and sized in a
 * world with y up, each bounded so that far from it only its bounding shape is evaluated, and
 * the ground they stand on. Each returns a lower bound of the distance to its shape, so any
 * union (min) of them is a lower bound of the distance to the whole scene. */
#include "fr/primitives.cl"
#include "fr/operators.cl"
#include "fr/menger.cl"
#include "fr/mandelbulb.cl"
#include "fr/kifs.cl"
#include "fr/recursive.cl"

/* A slab `thickness` thick under y = height, cut to a disc of `radius` about the y axis (an
 * endless plane would cross the scene's bounding sphere). Max of two exact distances. */
inline real_t sd_floor_disc(vec3_t p, scalar_t height, scalar_t radius, scalar_t thickness) {
  const real_t slab = fabs(p.y - to_real(height - thickness / 2)) - to_real(thickness / 2);
  const real_t disc = sqrt(p.x * p.x + p.z * p.z) - to_real(radius);
  return op_intersect(slab, disc);
}

/* The Menger sponge filling the cube of half-side `size` about `centre`. More than 0.25 size
 * from the cube, the cube's own distance serves (exact for the cube, below the sponge's), and
 * where every lane is that far the folds are skipped. */
inline real_t de_sponge_at(vec3_t p, vec3_t centre, scalar_t size, int level, real_t* trap) {
  const vec3_t q = p_translate(p, centre);
  const real_t to_cube = sd_box(q, v3s(size, size, size));
  *trap = to_real(1);
  if (all_lanes(to_cube > to_real(0.25 * size))) return to_cube;
  const real_t de =
      op_rescale(de_menger(p_scale(q, size), level, 3, v3s(1, 1, 1), 0, trap), size);
  return lane_select(to_cube > to_real(0.25 * size), to_cube, de);
}

/* The power-n Mandelbulb scaled by `size` about `centre`, its polar axis along world y (swapping
 * y and z is an isometry). Beyond its bounding sphere (radius 2^(1/(n-1)) size) plus 0.25 size,
 * the distance to that sphere, where the escape-time estimate over-estimates. */
inline real_t de_bulb_at(vec3_t p, vec3_t centre, scalar_t size, float power, int iterations,
                         real_t* trap) {
  const vec3_t q = p_scale(p_translate(p, centre), size);
  const real_t to_bound = v3_length(q) - to_real(exp2(1 / ((scalar_t)power - 1)));
  *trap = to_real(1);
  if (all_lanes(to_bound > to_real(0.25))) return to_bound * to_real(size);
  const real_t de = de_mandelbulb(v3(q.x, q.z, q.y), power, to_real(2), iterations, trap);
  return op_rescale(lane_select(to_bound > to_real(0.25), to_bound, de), size);
}

/* Knighty's KIFS (group 0 octahedral, 1 icosahedral, 2 tetrahedral) scaled by `size` about
 * `centre`; it lies in the ball of radius |offset| size, whose distance serves beyond 0.25 size. */
inline real_t de_kifs_at(vec3_t p, vec3_t centre, scalar_t size, int group, int iterations,
                         scalar_t scale, vec3_t offset, scalar_t angle_x, scalar_t angle_y,
                         scalar_t angle_z, real_t* trap) {
  const vec3_t q = p_scale(p_translate(p, centre), size);
  const real_t to_ball = v3_length(q) - v3_length(offset);
  *trap = to_real(1);
  if (all_lanes(to_ball > to_real(0.25))) return to_ball * to_real(size);
  real_t de;
  if (group == 0)
    de = de_kifs_octahedron(q, iterations, scale, offset, angle_x, angle_y, angle_z, trap);
  else if (group == 1)
    de = de_kifs_icosahedron(q, iterations, scale, offset, angle_x, angle_y, angle_z, trap);
  else
    de = de_kifs_tetrahedron(q, iterations, scale, offset, angle_x, angle_y, angle_z, trap);
  return op_rescale(lane_select(to_ball > to_real(0.25), to_ball, de), size);
}

/* A Pythagoras tree (fr/recursive.cl) standing at `base`, `size` its trunk's length, turned by
 * `turn` radians about y. */
inline real_t de_tree_at(vec3_t p, vec3_t base, scalar_t size, scalar_t turn, int levels,
                         scalar_t child_scale, scalar_t tilt, scalar_t width, real_t* trap) {
  const vec3_t q = p_scale(p_rotate_y(p_translate(p, base), turn), size);
  return op_rescale(de_pythagoras_tree(q, levels, child_scale, tilt, width, trap), size);
}
