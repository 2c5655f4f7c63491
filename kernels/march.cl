/* march.cl — sphere tracing inside the scene's bounding sphere. The one march loop: primary
 * rays and mirror bounces both use it. */

typedef struct march_result_t {
  real_t t;        /* distance along the ray to the hit (meaningful where hit) */
  mask_t hit;      /* the ray reached the surface */
  real_t steps;    /* DE evaluations spent, for step-count AO and statistics */
  real_t min_dist; /* closest approach to the surface (tracked only when glow is on) */
} march_result_t;

/* Entry and exit distances of the ray through the sphere |p| = radius; false where the ray
 * misses it or it lies behind the origin. */
inline mask_t intersect_bounds(ray_t ray, scalar_t radius, real_t* t_enter, real_t* t_exit) {
  real_t b = v3_dot(ray.origin, ray.dir);
  real_t c = v3_length2(ray.origin) - (real_t)(radius * radius);
  real_t disc = b * b - c;
  real_t root = sqrt(fmax(disc, (real_t)0));
  *t_enter = fmax(-b - root, (real_t)0);
  *t_exit = -b + root;
  return (disc > (real_t)0) & (*t_exit > (real_t)0);
}

/* Stage hook: glow.cl tracks the closest approach; otherwise nothing is tracked. */
#ifndef FR_MARCH_TRACK
#define FR_MARCH_TRACK(min_dist, dist, active)
#endif

/* Marches each lane until it is within the hit threshold of the surface, leaves the bounding
 * sphere or runs out of steps. `path_t` is the length already travelled (before a bounce), so
 * the threshold keeps following the pixel's footprint. Rays that run out of steps count as hits:
 * they are deep in a crevice, where a miss would show the sky through the surface.
 *
 * Over-relaxed (Keinert et al. 2014): each step is omega times the DE. Where the unbounding
 * spheres of two consecutive steps do not overlap, the step overshot the guarantee; the lane then
 * steps back and continues with omega = 1 — the fallback that makes relaxation safe for DEs that
 * are only roughly 1-Lipschitz. A hit is accepted only on a step that did not fail. The DE is
 * also scaled by fc->step_scale, and no step exceeds the bounding radius. */
march_result_t march(ray_t ray, real_t path_t, __constant const fr_frame_constants* fc,
                     __constant const scene_params_t* params) {
  real_t t, t_exit;
  mask_t active = intersect_bounds(ray, fc->bounding_radius, &t, &t_exit);
  t_exit = fmin(t_exit, (real_t)fc->max_distance);
  active &= t < t_exit;
  mask_t hit = FR_MASK_FALSE;
  real_t steps = (real_t)0;
  real_t min_dist = (real_t)FR_SCALAR_MAX;
  const real_t max_step = (real_t)fc->bounding_radius;
  real_t omega = (real_t)fc->relaxation;
  real_t previous_radius = (real_t)0;
  real_t step = (real_t)0;
  for (int i = 0; i < fc->max_steps && any_lane(active); ++i) {
    vec3_t p = v3_mad(ray.origin, ray.dir, t);
    real_t dist = scene_de(p, params) * (real_t)fc->step_scale;
    FR_MARCH_TRACK(min_dist, dist, active);
    real_t radius = fabs(dist);
    mask_t overshot = (omega > (real_t)1) & (radius + previous_radius < step);
    /* Overshot: go back to where the previous (safe) sphere ended, unrelaxed from here on. */
    step = lane_select(overshot, step - omega * step, fmin(dist * omega, max_step));
    omega = lane_select(overshot, 1, omega);
    previous_radius = radius;
    mask_t reached = active & !overshot & (dist < hit_threshold(fc, path_t + t, p));
    steps += mask_to_real(active);
    hit |= reached;
    active &= !reached;
    t = lane_select(active, t + step, t);
    active &= t < t_exit;
  }
  march_result_t r;
  r.t = t;
  r.hit = hit | active; /* out of steps */
  r.steps = steps;
  r.min_dist = min_dist;
  return r;
}
