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
 * Lanes stop once |z|^2 passes the bailout (their values frozen), so every lane computes exactly
 * the scalar formula. *trap receives min |z|^2 over the orbit, for colouring. */
#include "fr/folds.cl"

/* Amazing Surf's fold (Mandelbulber's "amazing surf", after Tom Lowe's box): the box fold on x and
 * y only; z is left as it is, so the box becomes a folded sheet. */
inline vec3_t p_fold_box_xy(vec3_t p, real_t limit) {
  return v3(2 * clamp(p.x, -limit, limit) - p.x, 2 * clamp(p.y, -limit, limit) - p.y, p.z);
}

/* The Mandelbox iteration shared by both: `surf` chooses the two-axis fold. */
inline real_t mandelbox_iterate(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                                scalar_t fixed_radius, scalar_t fold_limit, int surf,
                                real_t* trap) {
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
    vec3_t next = v3_add(v3_scale(folded, to_real(scale)), p);
    real_t next_dr = dr * factor * to_real(fabs(scale)) + to_real(1);
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
  return mandelbox_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 0, trap);
}

real_t de_amazing_surf(vec3_t p, int iterations, scalar_t scale, scalar_t min_radius,
                       scalar_t fixed_radius, scalar_t fold_limit, real_t* trap) {
  return mandelbox_iterate(p, iterations, scale, min_radius, fixed_radius, fold_limit, 1, trap);
}
