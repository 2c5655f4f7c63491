/* march.cl — sphere tracing inside the scene's bounding sphere. The one march loop: primary
 * rays and mirror bounces both use it. */

typedef struct march_result_t {
  real_t t;            /* distance along the ray to the hit (meaningful where hit) */
  mask_t hit;          /* the ray reached the surface, or ran out of steps (then also below) */
  mask_t out_of_steps; /* the step budget ended first: t is the best candidate, see below */
  mask_t inside;       /* the ray started inside the solid (DE below -eps at its origin) */
  real_t steps;        /* DE evaluations spent, for statistics */
  real_t ao_steps;     /* plain sphere-tracing steps (a relaxed step counts as its length over the
                          DE) until the ray first came within a pixel footprint of the
                          surface: step-count AO's measure, the same whatever the hit threshold
                          (the steps after that only refine the hit) and the step budget */
  real_t min_dist;     /* closest approach to the surface (tracked only when glow is on) */
} march_result_t;

/* Ray status codes written per pixel (render.cl) and counted by the host (renderer.hpp). */
#define FR_RAY_MISS 0
#define FR_RAY_HIT 1
#define FR_RAY_OUT_OF_STEPS 2
#define FR_RAY_INSIDE 3

/* Entry and exit distances of the ray through the scene's bounding sphere (|p - centre| =
 * radius); false where the ray misses it or it lies behind the origin. */
inline mask_t intersect_bounds(ray_t ray, __constant const fr_frame_constants* fc,
                               real_t* t_enter, real_t* t_exit) {
  const scalar_t radius = fc->bounding_radius;
  const vec3_t origin = FR_FROM_CENTRE(ray.origin);
  real_t b = v3_dot(origin, ray.dir);
  real_t c = v3_length2(origin) - (real_t)(radius * radius);
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

/* Marches each lane from where it enters the scene's bounding sphere until it is within the hit
 * threshold of the surface, leaves the sphere (a miss: there is no other maximum distance) or
 * runs out of steps. `path_t` is the length already travelled before this ray's origin (the
 * start plane, or a bounce), so the threshold keeps following the pixel's footprint. The march
 * starts no nearer than t_min (where the cone pre-pass, cone.cl, found the way free; else 0).
 *
 * Over-relaxed (Keinert et al. 2014): each step is omega times the DE. Where the unbounding
 * spheres of two consecutive steps do not overlap, the step overshot the guarantee; the lane then
 * steps back and continues with omega = 1 — the fallback that makes relaxation safe for DEs that
 * are only roughly 1-Lipschitz. A hit is accepted only on a step that did not fail. The DE is
 * also scaled by fc->step_scale, and no step exceeds the bounding radius.
 *
 * Documented results for the hard cases:
 *  - Origin on the surface (|DE| <= eps at the ray's own origin, not at a point where it entered
 *    the bounds from outside): the lane steps by at least eps and counts a hit only where the
 *    DE falls below -eps (it went through the surface) until the DE first exceeds eps; so
 *    looking away from a surface you stand on shows what is in front, and looking into it hits
 *    within a step or two. (A camera exactly at a singular point where the DE is 0, such as
 *    the Mandelbulb's centre, is on the surface in this sense.)
 *  - Origin inside the solid (DE < -eps at the first point): the lane stops there with `inside`
 *    set; render.cl shades it black (no light reaches inside a solid) at depth path_t.
 *  - Out of steps: the lane ends at its best candidate, the point with the smallest DE/eps seen
 *    (Keinert et al.'s "minimum error" point). If that point came within FR_CANDIDATE_MAX_ERROR
 *    thresholds of the surface (a ray deep in a crevice), it is shaded as surface there; else
 *    (a ray creeping past an edge) as a miss. Either way `out_of_steps` is set, and the host
 *    counts these rays and warns when there are many. */
#define FR_CANDIDATE_MAX_ERROR 4
/* de_sign: 1 marches the solid's outside; -1 (per lane) its inside, the DE negated, towards where
 * a ray inside a transparent solid leaves it (path.cl's glass). t_max (per lane): a ray that
 * gets this far without a hit ends there as a miss (path.cl's subsurface walk: the next
 * scattering); FR_SCALAR_MAX for no limit but the bounds. */
march_result_t march(ray_t ray, real_t path_t, real_t t_min, real_t t_max, int max_steps,
                     real_t de_sign, __constant const fr_frame_constants* fc,
                     __constant const scene_params_t* params FR_COUNTS_PARAM) {
  real_t t, t_exit;
  mask_t active = intersect_bounds(ray, fc, &t, &t_exit);
  t_exit = fmin(t_exit, t_max);
  t = fmax(t, t_min);
  active &= t < t_exit;
  mask_t hit = FR_MASK_FALSE, inside = FR_MASK_FALSE, leaving = FR_MASK_FALSE;
  real_t steps = (real_t)0, ao_steps = (real_t)0;
  mask_t near = FR_MASK_FALSE;
  real_t min_dist = (real_t)FR_SCALAR_MAX;
  const real_t max_step = (real_t)fc->bounding_radius;
#if FR_RELAX_ADAPTIVE
  real_t omega = (real_t)1; /* of the step that led here: the first is plain */
  mask_t plain_next = FR_MASK_TRUE;
#else
  real_t omega = (real_t)fc->relaxation;
#endif
  real_t previous_radius = (real_t)0;
  real_t step = (real_t)0;
  real_t best_t = t, best_error = (real_t)FR_SCALAR_MAX;
  for (int i = 0; i < max_steps && any_lane(active); ++i) {
    vec3_t p = v3_mad(ray.origin, ray.dir, t);
    real_t dist = de_sign * scene_de(p, params) * (real_t)fc->step_scale;
    FR_COUNT(FR_COUNT_MARCH, active, 1);
    real_t eps = hit_threshold(fc, path_t + t, p);
    FR_MARCH_TRACK(min_dist, dist, active);
    steps += mask_to_real(active);
    /* Step-count AO counts the steps plain sphere tracing would have taken (march_result_t), so
     * that occlusion does not change with the relaxation: below, after the step is known. */
    const mask_t ao_counting = active & !near;
    near |= dist < (real_t)(0.5f * fc->pixel_angle_rad) * (path_t + t);
    /* The first point is the ray's own origin (not where it entered the bounds from outside):
     * below -eps it is inside the solid; within eps it is on a surface, and the lane is
     * "leaving" until the DE first exceeds eps. */
    if (i == 0) {
      const mask_t at_origin = t <= (real_t)0;
      inside = active & at_origin & (dist < -eps);
      active &= !inside;
      leaving = active & at_origin & (dist < eps);
    }
    real_t radius = fabs(dist);
    /* A relaxed step overshot where its sphere and the last one do not overlap, or where it
     * landed inside the solid (a step that went through a surface can land deep enough for the
     * spheres to overlap). */
    mask_t overshot = !leaving & (omega > (real_t)1) &
                      ((radius + previous_radius < step) | (dist < -eps));
#if FR_RELAX_ADAPTIVE
    /* The DE's slope along the ray over the last step. Were it linear, the next sphere would
     * still overlap this one for any omega <= 2 / (1 - slope): 1 heading straight at a surface
     * (slope -1), 2 running parallel to one (slope 0). Take 95% of that, at most the user's
     * relaxation; plain after a step back. Overshot: back to where the previous (safe) sphere
     * ended, exactly, and relax again from there (Bán and Valasek 2023's automatic relaxation,
     * with Keinert et al.'s overlap test as its guard). */
    const real_t slope = (radius - previous_radius) / fmax(step, (real_t)FR_SCALAR_MIN);
    const real_t next_omega = lane_select(
        plain_next, 1,
        clamp((real_t)1.9 / fmax((real_t)1 - slope, (real_t)FR_SCALAR_EPSILON), (real_t)1,
              (real_t)fc->relaxation));
    step = lane_select(overshot, previous_radius - step, fmin(dist * next_omega, max_step));
    omega = lane_select(overshot, 1, next_omega);
    plain_next = overshot;
#else
    /* Overshot: go back to where the previous (safe) sphere ended, unrelaxed from here on. */
    step = lane_select(overshot, step - omega * step, fmin(dist * omega, max_step));
#endif
    /* Leaving a surface: steps of at least eps, unrelaxed; a hit only once the ray has gone
     * through it (DE below -eps), so looking away from the surface is never a hit at the eye. */
    step = lane_select(leaving, fmin(fmax(radius, eps), max_step), step);
    omega = lane_select(overshot | leaving, 1, omega);
    previous_radius = lane_select(overshot, previous_radius, radius);
    mask_t reached = active & !overshot & ((leaving & (dist < -eps)) | (!leaving & (dist < eps)));
    leaving &= dist < eps;
    /* The best candidate so far; the surface a lane is leaving is not one. */
    const real_t error = dist / eps;
    mask_t better = active & !overshot & !leaving & (error < best_error);
    best_t = lane_select(better, t, best_t);
    best_error = lane_select(better, error, best_error);
    /* A step of s over a DE of d is s / d plain steps; a step back is none; the evaluation that
     * found the surface is one. */
    const real_t plain_steps = lane_select(
        reached, 1, lane_select(overshot, 0, fmin(step / fmax(radius, (real_t)FR_SCALAR_MIN),
                                                  (real_t)fc->relaxation)));
    ao_steps += lane_select(ao_counting, plain_steps, 0);
    hit |= reached;
    active &= !reached;
    t = lane_select(active, t + step, t);
    active &= t < t_exit;
  }
  /* Refinement: the hit stopped up to eps in front of the surface (more at grazing angles: the
   * silhouette bias); a few more plain steps of the DE, a lower bound, close that gap without
   * ever passing through. */
  const mask_t converged = hit;
  for (int i = 0; i < fc->refine_steps && any_lane(converged); ++i) {
    const real_t dist =
        de_sign * scene_de(v3_mad(ray.origin, ray.dir, t), params) * (real_t)fc->step_scale;
    FR_COUNT(FR_COUNT_MARCH, converged, 1);
    t = lane_select(converged, t + fmax(dist, (real_t)0), t);
  }
  march_result_t r;
  r.out_of_steps = active;
  r.t = lane_select(active, best_t, t);
  r.hit = hit | (active & (best_error <= (real_t)FR_CANDIDATE_MAX_ERROR));
  r.inside = inside;
  r.steps = steps;
  r.ao_steps = ao_steps;
  r.min_dist = min_dist;
  return r;
}
