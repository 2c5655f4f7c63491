/* fr/mandelbox_dd.cl — Tom Lowe's Mandelbox (fr/mandelbox.cl) at a point given in double-double
 * (fr/dd.cl), for views past what double resolves.
 *
 * The same iteration, z <- scale * fold(z) + p with dr <- dr * |scale| * (sphere fold's factor)
 * + 1, and the estimate |z| / |dr|. Only its first iterations need the pairs: a rounding of z at
 * an iteration where the running derivative is dr moves the estimate's point by that rounding over
 * dr (the folds and the scaling carry a change of z as they carry a change of p, times dr), so once
 * dr * pixel exceeds 1000 ulps of max(|z|, |p|) double's roundings cost less than a thousandth of
 * a pixel and the rest runs in double. The Mandelbox's dr never shrinks (the sphere fold's factor
 * is at least 1, |scale| > 1), so a lane switches once; the loop keeps the pairs until every lane
 * of the work-item may switch. `pixel` is the size the estimate must resolve (a pixel's footprint
 * at the point; 0 keeps every iteration in pairs). The Julia and rotated boxes run the same loop
 * (mandelbox_dd_iterate). */
#include "fr/dd.cl"
#include "fr/folds.cl"
#include "fr/operators.cl"
#include "fr/mandelbox.cl"
#include "fr/dd_folds.cl"

/* The iteration shared by the box, its Julia form and the rotated box (mandelbox_iterate's): the
 * Julia form adds the constant c (a double) instead of p, and its dr gets no +1; the rotation
 * (Euler angles in radians, x then y then z) follows the folds. Both keep dr from shrinking, so a
 * lane's switch to double stays final. For the Julia form p enters only the first iteration: the
 * bound's size is max(|z|, |c|). Always inlined, so each form's constants fold away: a call
 * that passed 768-byte pairs of vectors by memory cost the box 15% (measured with bench). */
__attribute__((always_inline)) inline real_t mandelbox_dd_iterate(
    dd3_t p, int iterations, scalar_t scale, scalar_t min_radius, scalar_t fixed_radius,
    scalar_t fold_limit, int julia, vec3_t c, scalar_t angle_x, scalar_t angle_y,
    scalar_t angle_z, real_t pixel) {
  const real_t limit = to_real(fold_limit);
  const real_t bailout2 = to_real(1e8);
  const real_t dr_added = julia ? to_real(0) : to_real(1);
  const real_t p_size = julia ? v3_length(c) : sqrt(dd_to_real(dd3_length2(p)));
  const dd3_t added = julia ? dd3_from(c) : p;
  const dd_sphere_fold_t sphere_fold = dd_sphere_fold_prepare(min_radius, fixed_radius);
  /* 1000 ulps of double, relative */
  const real_t switch_ulps = to_real(1000 * DBL_EPSILON);
  dd3_t z = p;
  real_t dr = to_real(1);
  /* |z|^2 only decides the bailout and the switch: double serves. */
  real_t r2 = p_size * p_size;
  int i = 0;
  for (; i < iterations; ++i) {
    const real_t size = fmax(sqrt(fmax(r2, (real_t)0)), p_size);
    const mask_t needs_pairs = dr * pixel <= switch_ulps * size;
    const mask_t live = r2 < bailout2;
    if (!any_lane(live)) break;
    if (!any_lane(live & needs_pairs)) break; /* the rest in double, below */
    const dd3_t folded = dd3_fold_box(z, limit);
    const dd_t factor = dd_sphere_fold_factor(dd3_length2(folded), &sphere_fold);
    /* scale x factor first: one product of pairs a coordinate, not two. */
    const dd3_t turned = dd3_rotate_xyz(dd3_scale(folded, dd_mul_d(factor, to_real(scale))),
                                        angle_x, angle_y, angle_z);
    const dd3_t next = dd3_add(turned, added);
    const real_t next_dr = dr * factor.hi * to_real(fabs(scale)) + dr_added;
    z = dd3_select(live, next, z);
    dr = lane_select(live, next_dr, dr);
    r2 = lane_select(live, v3_length2(dd3_to_v3(z)), r2);
  }
  /* A lane whose orbit ended in pairs (escaped, or every iteration done) takes |z| from the
   * pairs: rounded to double it would move the estimate in steps of an ulp of |z| over dr, coarse
   * where dr is still small (few iterations, a deep view). */
  /* (i is the same in every lane: a scalar condition picks the whole mask, never ORs into it,
   * since a vector select reads each lane's top bit.) */
  const mask_t ended_in_pairs = i >= iterations ? FR_MASK_TRUE : (r2 >= bailout2);
  const dd_t r_pairs = dd_sqrt(dd3_length2(z));
  /* The rest in double: p rounded to double costs at most an ulp of |p| over dr (as above). */
  vec3_t zd = dd3_to_v3(z);
  const vec3_t pd = julia ? c : dd3_to_v3(p);
  real_t r2d = v3_length2(zd);
  for (; i < iterations; ++i) {
    const mask_t live = r2d < bailout2;
    if (!any_lane(live)) break;
    vec3_t folded = p_fold_box(zd, limit);
    real_t factor = to_real(1);
    folded = p_fold_sphere(folded, to_real(min_radius), to_real(fixed_radius), &factor);
    folded = p_rotate_xyz(folded, angle_x, angle_y, angle_z);
    const vec3_t next = v3_add(v3_scale(folded, to_real(scale)), pd);
    const real_t next_dr = dr * factor * to_real(fabs(scale)) + dr_added;
    zd = v3_select(live, next, zd);
    dr = lane_select(live, next_dr, dr);
    r2d = lane_select(live, v3_length2(zd), r2d);
  }
  return lane_select(ended_in_pairs, r_pairs.hi / fabs(dr) + r_pairs.lo / fabs(dr),
                     sqrt(r2d) / fabs(dr));
}

real_t de_mandelbox_dd(dd3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                       scalar_t fixed_radius, scalar_t fold_limit, real_t pixel) {
  return mandelbox_dd_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 0,
                              v3s(0, 0, 0), 0, 0, 0, pixel);
}

/* Lowe's box as a Julia set (de_mandelbox_julia) in pairs. */
real_t de_mandelbox_julia_dd(dd3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                             scalar_t fixed_radius, scalar_t fold_limit, vec3_t c, real_t pixel) {
  return mandelbox_dd_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 1, c, 0,
                              0, 0, pixel);
}

/* The rotated box (de_mandelbox_rotated) in pairs. */
real_t de_mandelbox_rotated_dd(dd3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                               scalar_t fixed_radius, scalar_t fold_limit, scalar_t angle_x,
                               scalar_t angle_y, scalar_t angle_z, real_t pixel) {
  return mandelbox_dd_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 0,
                              v3s(0, 0, 0), angle_x, angle_y, angle_z, pixel);
}
