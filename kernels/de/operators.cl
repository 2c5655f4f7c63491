/* fr/operators.cl — combining distances (op_*) and transforming the domain (p_*).
 *
 * Combinations of exact distances: op_union is exact outside both shapes and a bound inside;
 * op_intersect and op_subtract are bounds. The smooth versions blend over a width k > 0 with the
 * polynomial smooth minimum and are bounds.
 *
 * Smooth minimum, derived: with h = clamp(1/2 + (b - a) / (2k), 0, 1), the blend
 *   smin(a, b) = mix(b, a, h) - k h (1 - h)
 * equals min(a, b) when |a - b| >= k (h is 0 or 1 and the correction vanishes), is continuous
 * and C1 in between, and reaches min - k/4 at a = b. (Some texts write the correction with
 * its blend variable and its width swapped; this is the form used here.) Then
 *   smooth intersection = -smin(-a, -b)  and  smooth subtraction of a from b = -smin(-b, a),
 * which expand to the two functions below. */

inline real_t op_union(real_t a, real_t b) { return fmin(a, b); }
/* b with a cut away. */
inline real_t op_subtract(real_t a, real_t b) { return fmax(-a, b); }
inline real_t op_intersect(real_t a, real_t b) { return fmax(a, b); }

inline real_t op_smooth_union(real_t a, real_t b, real_t k) {
  real_t h = clamp(to_real(0.5) + to_real(0.5) * (b - a) / k, to_real(0), to_real(1));
  return mix(b, a, h) - k * h * (to_real(1) - h);
}
inline real_t op_smooth_intersect(real_t a, real_t b, real_t k) {
  real_t h = clamp(to_real(0.5) - to_real(0.5) * (b - a) / k, to_real(0), to_real(1));
  return mix(b, a, h) + k * h * (to_real(1) - h);
}
/* b with a smoothly cut away. */
inline real_t op_smooth_subtract(real_t a, real_t b, real_t k) {
  real_t h = clamp(to_real(0.5) - to_real(0.5) * (b + a) / k, to_real(0), to_real(1));
  return mix(b, -a, h) + k * h * (to_real(1) - h);
}

/* Domain transforms: evaluate a shape at the returned point. Isometries keep distances exact. */
inline vec3_t p_translate(vec3_t p, vec3_t offset) { return v3_sub(p, offset); }

/* Rotation of the shape by `angle` radians about an axis: the point is rotated by -angle. */
inline vec3_t p_rotate_x(vec3_t p, scalar_t angle) {
  real_t c = (real_t)cos(angle), s = (real_t)sin(angle);
  return v3(p.x, c * p.y + s * p.z, -s * p.y + c * p.z);
}
inline vec3_t p_rotate_y(vec3_t p, scalar_t angle) {
  real_t c = (real_t)cos(angle), s = (real_t)sin(angle);
  return v3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}
inline vec3_t p_rotate_z(vec3_t p, scalar_t angle) {
  real_t c = (real_t)cos(angle), s = (real_t)sin(angle);
  return v3(c * p.x + s * p.y, -s * p.x + c * p.y, p.z);
}

/* Rotation by Euler angles (radians, one value for all lanes) about x, then y, then z; zero
 * angles cost nothing. */
inline vec3_t p_rotate_xyz(vec3_t p, scalar_t angle_x, scalar_t angle_y, scalar_t angle_z) {
  vec3_t q = p;
  if (angle_x != 0) q = p_rotate_x(q, angle_x);
  if (angle_y != 0) q = p_rotate_y(q, angle_y);
  if (angle_z != 0) q = p_rotate_z(q, angle_z);
  return q;
}

/* Uniform scale by s > 0: evaluate d = shape(p_scale(p, s)) and return op_rescale(d, s), which
 * keeps the distance exact (a scaled shape's distances scale by s). */
inline vec3_t p_scale(vec3_t p, scalar_t s) { return v3_scale(p, (real_t)(1 / s)); }
inline real_t op_rescale(real_t d, scalar_t s) { return d * (real_t)s; }

/* Infinite repetition with the given period on each axis (0: no repetition on that axis).
 * Exact while the shape fits in its cell. */
inline vec3_t p_repeat(vec3_t p, vec3_t period) {
  vec3_t q = p;
  q.x = lane_select(period.x > 0, p.x - period.x * rint(p.x / period.x), p.x);
  q.y = lane_select(period.y > 0, p.y - period.y * rint(p.y / period.y), p.y);
  q.z = lane_select(period.z > 0, p.z - period.z * rint(p.z / period.z), p.z);
  return q;
}

/* Twist about y by k radians per unit of height. Not distance-preserving: the gradient grows to
 * sqrt(1 + (k r)^2) at radius r, so divide the result by that (or render with render.step_scale < 1). */
inline vec3_t p_twist(vec3_t p, scalar_t k) {
  real_t a = (real_t)k * p.y;
  real_t c = cos(a), s = sin(a);
  return v3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}

/* Bend in the xy plane by k radians per unit along x. Not distance-preserving (like p_twist). */
inline vec3_t p_bend(vec3_t p, scalar_t k) {
  real_t a = (real_t)k * p.x;
  real_t c = cos(a), s = sin(a);
  return v3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
}

/* Inversion in the sphere of squared radius radius2 about `center`: p -> center + (p - center)
 * radius2 / |p - center|^2. It turns a shape inside out about the centre (a point of the shape's
 * outside), mapping lengths near p by radius2 / |p - center|^2. */
inline vec3_t p_invert_sphere(vec3_t p, vec3_t center, scalar_t radius2) {
  const vec3_t d = v3_sub(p, center);
  const real_t k = to_real(radius2) / fmax(v3_length2(d), to_real(1e-30));
  return v3_add(center, v3_scale(d, k));
}

/* The distance bound at p for the inverted shape, from a lower bound `de` of the distance to the
 * shape at p's image (p_invert_sphere) and rho = |p - center|. The ball of radius
 * de rho^2 / (radius2 + de rho) about p maps into the ball of radius de about the image (its
 * farthest image point lies radius2 delta / (rho (rho - delta)) from it), so that ball misses the
 * inverted shape: an exact lower bound, not a first-order estimate. Inside (de < 0) the sign is
 * what matters; the local scale rho^2 / radius2 serves. */
inline real_t op_invert_de(real_t de, real_t rho, scalar_t radius2) {
  return lane_select(de >= 0, de * rho * rho / (to_real(radius2) + de * rho),
                     de * rho * rho / to_real(radius2));
}
