/* fr/folds.cl — the space folds escape-time and IFS fractals are built from. Each maps the point
 * into a fundamental domain of a symmetry; folds that are reflections are 1-Lipschitz, so a
 * distance evaluated after them is still a lower bound. */

/* Reflection into the positive octant. */
inline vec3_t p_fold_abs(vec3_t p) { return v3_abs(p); }

/* Reflection across the plane dot(p, n) = d (n unit) for points on its negative side. */
inline vec3_t p_fold_plane(vec3_t p, vec3_t n, real_t d) {
  real_t side = v3_dot(p, n) - d;
  return v3_select(side < 0, v3_mad(p, n, -2 * side), p);
}

/* Mandelbox box fold: reflect each coordinate beyond +-limit back inside (2 clamp(p) - p). */
inline vec3_t p_fold_box(vec3_t p, real_t limit) {
  return v3(2 * clamp(p.x, -limit, limit) - p.x, 2 * clamp(p.y, -limit, limit) - p.y,
            2 * clamp(p.z, -limit, limit) - p.z);
}

/* Mandelbox sphere fold: inside min_radius scale up by (fixed/min)^2, between min and fixed
 * radius invert. Multiplies *dr (the running derivative) by the same factor. */
inline vec3_t p_fold_sphere(vec3_t p, real_t min_radius, real_t fixed_radius, real_t* dr) {
  real_t r2 = v3_length2(p);
  real_t min2 = min_radius * min_radius, fixed2 = fixed_radius * fixed_radius;
  real_t factor = lane_select(r2 < min2, fixed2 / min2,
                              lane_select(r2 < fixed2, fixed2 / fmax(r2, to_real(1e-30)), 1));
  *dr *= factor;
  return v3_scale(p, factor);
}

/* Menger fold: the positive octant, then the coordinates sorted so that x >= y >= z (three
 * reflections across the planes x = y, x = z, y = z). */
inline vec3_t p_fold_menger(vec3_t p) {
  vec3_t q = v3_abs(p);
  real_t t;
  mask_t m = q.x < q.y;
  t = q.x; q.x = lane_select(m, q.y, q.x); q.y = lane_select(m, t, q.y);
  m = q.x < q.z;
  t = q.x; q.x = lane_select(m, q.z, q.x); q.z = lane_select(m, t, q.z);
  m = q.y < q.z;
  t = q.y; q.y = lane_select(m, q.z, q.y); q.z = lane_select(m, t, q.z);
  return q;
}

/* Sierpinski fold: reflections across x + y = 0, x + z = 0 and y + z = 0 (each for points on
 * the negative side), which bring a point next to the tetrahedron's vertex (1, 1, 1). */
inline vec3_t p_fold_sierpinski(vec3_t p) {
  vec3_t q = p;
  real_t t;
  mask_t m = q.x + q.y < 0;
  t = q.x; q.x = lane_select(m, -q.y, q.x); q.y = lane_select(m, -t, q.y);
  m = q.x + q.z < 0;
  t = q.x; q.x = lane_select(m, -q.z, q.x); q.z = lane_select(m, -t, q.z);
  m = q.y + q.z < 0;
  t = q.y; q.y = lane_select(m, -q.z, q.y); q.z = lane_select(m, -t, q.z);
  return q;
}
