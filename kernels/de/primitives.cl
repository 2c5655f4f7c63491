/* fr/primitives.cl — distance functions of simple shapes, centred at the origin.
 * sd_* are exact Euclidean distances (negative inside); de_* are lower bounds (never larger than
 * the true distance, so sphere tracing stays safe, but they may step more slowly). */

/* Sphere of radius r. Exact. */
inline real_t sd_sphere(vec3_t p, real_t r) { return v3_length(p) - r; }

/* Axis-aligned box with half-extents b. Exact: outside, the distance to the nearest point of the
 * box; inside, minus the distance to the nearest face. */
inline real_t sd_box(vec3_t p, vec3_t b) {
  vec3_t q = v3_sub(v3_abs(p), b);
  real_t outside = v3_length(v3_max(q, v3s(0, 0, 0)));
  real_t inside = fmin(fmax(q.x, fmax(q.y, q.z)), to_real(0));
  return outside + inside;
}

/* Box with half-extents b whose edges are rounded with radius r (the result's half-extent is b).
 * Exact. */
inline real_t sd_round_box(vec3_t p, vec3_t b, real_t r) {
  return sd_box(p, v3_sub(b, v3(r, r, r))) - r;
}

/* Torus in the xz plane: ring radius R (centre to tube centre), tube radius r. Exact. */
inline real_t sd_torus(vec3_t p, real_t ring_radius, real_t tube_radius) {
  real_t ring = sqrt(p.x * p.x + p.z * p.z) - ring_radius;
  return sqrt(ring * ring + p.y * p.y) - tube_radius;
}

/* Plane through the origin-offset point: unit normal n, at signed distance h from the origin
 * along n (points with dot(p, n) > h are outside). Exact. */
inline real_t sd_plane(vec3_t p, vec3_t n, real_t h) { return v3_dot(p, n) - h; }

/* Capsule: the segment from a to b, thickened by r. Exact. */
inline real_t sd_capsule(vec3_t p, vec3_t a, vec3_t b, real_t r) {
  vec3_t pa = v3_sub(p, a), ba = v3_sub(b, a);
  real_t h = clamp(v3_dot(pa, ba) / v3_dot(ba, ba), to_real(0), to_real(1));
  return v3_length(v3_sub(pa, v3_scale(ba, h))) - r;
}

/* Capped cylinder along y: radius r, half-height h. Exact. */
inline real_t sd_cylinder(vec3_t p, real_t r, real_t h) {
  real_t dx = sqrt(p.x * p.x + p.z * p.z) - r;
  real_t dy = fabs(p.y) - h;
  real_t outside = sqrt(fmax(dx, to_real(0)) * fmax(dx, to_real(0)) + fmax(dy, to_real(0)) * fmax(dy, to_real(0)));
  return outside + fmin(fmax(dx, dy), to_real(0));
}

/* Regular tetrahedron with vertices (s,s,s), (s,-s,-s), (-s,s,-s), (-s,-s,s): the largest of the
 * four face-plane distances. A bound (exact inside and in front of the faces' interiors, an
 * under-estimate near edges and vertices). */
inline real_t de_tetrahedron(vec3_t p, real_t s) {
  const real_t k = to_real(0.57735026918962576);  /* 1 / sqrt 3 */
  real_t a = fmax(-p.x - p.y - p.z, -p.x + p.y + p.z);
  real_t b = fmax(p.x - p.y + p.z, p.x + p.y - p.z);
  return (fmax(a, b) - s) * k;
}

/* Regular octahedron |x| + |y| + |z| = s. A bound, exact in front of the faces' interiors. */
inline real_t de_octahedron(vec3_t p, real_t s) {
  return (fabs(p.x) + fabs(p.y) + fabs(p.z) - s) * to_real(0.57735026918962576);
}
