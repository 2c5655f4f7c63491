/* reflect.cl — mirror bounces: after a hit on a reflective surface, the ray continues in the
 * mirror direction from just off the surface, up to max_bounces times (render.cl's loop). */

#define FR_MAX_BOUNCES(fc) ((fc)->max_bounces)

inline ray_t mirror_ray(ray_t ray, vec3_t p, vec3_t n, real_t h) {
  ray_t next;
  next.dir = v3_mad(ray.dir, n, -2 * v3_dot(ray.dir, n));
  next.origin = v3_mad(p, n, 2 * h);
  return next;
}

#define FR_BOUNCE(ray, p, n, h) ray = mirror_ray(ray, p, n, h)
