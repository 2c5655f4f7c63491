/* fr/mandelbox.cl — Tom Lowe's Mandelbox ("Amazing Box", fractalforums.com, 2010) and its
 * Amazing Surf variant.
 *
 * Each iteration folds the point (box fold to +-fold_limit, then sphere fold with min_radius and
 * fixed_radius), scales it and adds the starting point: z <- scale * fold(z) + p. The running
 * derivative follows the same steps, dr <- dr * |scale| * (sphere fold's factor) + 1, and the
 * estimate is |z| / |dr|. Folds are 1-Lipschitz away from the sphere fold's inversion, whose
 * factor dr carries, so the estimate is a lower bound near the set. With scale 2 (or -1.5), min
 * radius 0.5, fixed radius 1 and fold limit 1 it gives Lowe's classic shapes; for |scale| > 1 the
 * set lies in the cube |x_i| <= 2 (|scale| + 1) / (|scale| - 1) (Lowe's bound: a point outside
 * it escapes).
 *
 * Variants on the same loop: the Julia form adds a constant c instead of p (Lowe's box as a Julia
 * set; dr then gets no +1), a rotation after the folds (an isometry: dr unchanged) twists the box
 * as Mandelbulber's rotated boxes do, and the 4D box (after Lowe, as in Mandelbulber's "Amazing
 * Box 4D") folds four coordinates and is sliced at w = slice_w (the slice w = 0 is the 3D box).
 *
 * Lanes stop once |z|^2 passes the bailout (their values frozen), so every lane computes exactly
 * the scalar formula. *trap receives min |z|^2 over the orbit, for colouring. */
#include "fr/folds.cl"
#include "fr/operators.cl"

/* Amazing Surf's fold (Mandelbulber's "amazing surf", after Tom Lowe's box): the box fold on x and
 * y only; z is left as it is, so the box becomes a folded sheet. */
inline vec3_t p_fold_box_xy(vec3_t p, real_t limit) {
  return v3(2 * clamp(p.x, -limit, limit) - p.x, 2 * clamp(p.y, -limit, limit) - p.y, p.z);
}

/* The Mandelbox iteration shared by the 3D forms: `surf` chooses the two-axis fold, `julia` adds
 * c instead of p, and the Euler angles (radians, x then y then z) rotate after the folds. */
inline real_t mandelbox_iterate(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                                scalar_t fixed_radius, scalar_t fold_limit, int surf, int julia,
                                vec3_t c, scalar_t angle_x, scalar_t angle_y, scalar_t angle_z,
                                real_t* trap) {
  const vec3_t added = julia ? c : p;
  const real_t dr_added = julia ? to_real(0) : to_real(1);
  vec3_t z = p;
  real_t dr = to_real(1);
  real_t r2 = v3_length2(z);
  real_t orbit_min = r2;
  const real_t bailout2 = to_real(1e8);
  for (int i = 0; i < iterations; ++i) {
    mask_t live = r2 < bailout2;
    if (!any_lane(live)) break;
    vec3_t folded = surf ? p_fold_box_xy(z, to_real(fold_limit)) : p_fold_box(z, to_real(fold_limit));
    real_t factor = to_real(1);
    folded = p_fold_sphere(folded, to_real(min_radius), to_real(fixed_radius), &factor);
    folded = p_rotate_xyz(folded, angle_x, angle_y, angle_z);
    vec3_t next = v3_add(v3_scale(folded, to_real(scale)), added);
    real_t next_dr = dr * factor * to_real(fabs(scale)) + dr_added;
    z = v3_select(live, next, z);
    dr = lane_select(live, next_dr, dr);
    r2 = lane_select(live, v3_length2(z), r2);
    orbit_min = lane_select(live, fmin(orbit_min, r2), orbit_min);
  }
  *trap = orbit_min;
  return sqrt(r2) / fabs(dr);
}

real_t de_mandelbox(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                    scalar_t fixed_radius, scalar_t fold_limit, real_t* trap) {
  return mandelbox_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 0, 0, p, 0,
                           0, 0, trap);
}

real_t de_amazing_surf(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                       scalar_t fixed_radius, scalar_t fold_limit, real_t* trap) {
  return mandelbox_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 1, 0, p, 0,
                           0, 0, trap);
}

/* Lowe's box as a Julia set: z <- scale * fold(z) + c. */
real_t de_mandelbox_julia(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                          scalar_t fixed_radius, scalar_t fold_limit, vec3_t c, real_t* trap) {
  return mandelbox_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 0, 1, c, 0,
                           0, 0, trap);
}

/* The box with a rotation after each fold (Euler angles in radians, x then y then z). */
real_t de_mandelbox_rotated(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                            scalar_t fixed_radius, scalar_t fold_limit, scalar_t angle_x,
                            scalar_t angle_y, scalar_t angle_z, real_t* trap) {
  return mandelbox_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 0, 0, p,
                           angle_x, angle_y, angle_z, trap);
}

/* The 4D box sliced at w = slice_w: box fold on x, y, z and w, sphere fold on the 4D radius,
 * z <- scale * fold(z) + (p, slice_w). The 4D distance bound |z| / |dr| bounds the distance to
 * the slice too (a slice's points are the set's points). */
real_t de_mandelbox_4d(vec3_t p, scalar_t slice_w, int iterations, scalar_t scale,
                       scalar_t min_radius, scalar_t fixed_radius, scalar_t fold_limit,
                       real_t* trap) {
  vec3_t z = p;
  real_t w = to_real(slice_w);
  real_t dr = to_real(1);
  real_t r2 = v3_length2(z) + w * w;
  real_t orbit_min = r2;
  const real_t limit = to_real(fold_limit);
  const real_t min2 = to_real(min_radius * min_radius), fixed2 = to_real(fixed_radius * fixed_radius);
  for (int i = 0; i < iterations; ++i) {
    mask_t live = r2 < to_real(1e8);
    if (!any_lane(live)) break;
    vec3_t q = p_fold_box(z, limit);
    real_t qw = 2 * clamp(w, -limit, limit) - w;
    const real_t q2 = v3_length2(q) + qw * qw;
    const real_t factor =
        lane_select(q2 < min2, fixed2 / min2, lane_select(q2 < fixed2, fixed2 / fmax(q2, to_real(1e-30)), 1));
    const real_t s = factor * to_real(scale);
    z = v3_select(live, v3_add(v3_scale(q, s), p), z);
    w = lane_select(live, qw * s + to_real(slice_w), w);
    dr = lane_select(live, dr * factor * to_real(fabs(scale)) + to_real(1), dr);
    r2 = lane_select(live, v3_length2(z) + w * w, r2);
    orbit_min = lane_select(live, fmin(orbit_min, r2), orbit_min);
  }
  *trap = orbit_min;
  return sqrt(r2) / fabs(dr);
}
