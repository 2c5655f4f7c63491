/* render.cl — the frame kernel: one work-item per tile of FR_TILE_W x FR_TILE_H pixels (one
 * pixel at FR_LANES 1). Lens -> march -> normal -> surface -> AO -> lights and shadows -> fog,
 * then mirror bounces; the sample is mixed into the running mean in hdr_rgba (progressive
 * anti-aliasing and depth of field). Also writes, for the primary ray, the hit depth from the eye
 * (+inf for a miss), the DE steps, the occlusion and first-light shadow factors, the ray's
 * status (FR_RAY_* in march.cl), the unit surface normal and the surface's albedo (both zero for
 * a miss): the passes an OpenEXR file carries for compositing.
 *
 * Optional stages (lens.cl, cone.cl, glow.cl, ao.cl, shadow.cl, fog.cl, reflect.cl) are pasted in only
 * when the scene needs them and they are switched on; each defines its hook, and a hook with no
 * stage does nothing, so none of that stage's code is in the kernel. */

#ifndef FR_APPLY_LENS
#define FR_APPLY_LENS(ray, px, py)
#endif
#ifndef FR_APPLY_GLOW
#define FR_APPLY_GLOW(color, m, miss)
#endif
#ifndef FR_APPLY_AO
#define FR_APPLY_AO(ao, p, n, m)
#endif
#ifndef FR_AO_EVALS
#define FR_AO_EVALS 0
#endif
#ifndef FR_APPLY_FOG
#define FR_APPLY_FOG(color, t)
#endif
#ifndef FR_CONE_START
#define FR_CONE_START(t, ao_steps)
#endif
#ifndef FR_MAX_BOUNCES
#define FR_MAX_BOUNCES(fc) 0
#define FR_BOUNCE(ray, p, n, h)
#endif

__kernel void fr_render(FR_RENDER_KERNEL_PARAMS) {
  FR_COUNTS_BEGIN;
  FR_RENDER_TILE;

  real_t path_t;
  ray_t ray = camera_ray(fc, px, py, (real_t)fc->jitter_x, (real_t)fc->jitter_y, &path_t);
  FR_APPLY_LENS(ray, px, py);

  vec3_t color = v3s(0, 0, 0);
  vec3_t throughput = v3s(1, 1, 1);
  mask_t active = FR_MASK_TRUE;
  real_t first_depth = (real_t)INFINITY, first_steps = (real_t)0, first_status = (real_t)0;
  real_t first_ao = (real_t)1, first_shadow = (real_t)1;
  vec3_t first_normal = v3s(0, 0, 0), first_albedo = v3s(0, 0, 0);
  /* Where the cone pre-pass (cone.cl) lets the primary ray start, and the AO steps it saved. */
  real_t cone_from = (real_t)0, cone_ao = (real_t)0;
  FR_CONE_START(cone_from, cone_ao);
  const int bounces = FR_MAX_BOUNCES(fc);
  for (int bounce = 0; bounce <= bounces; ++bounce) {
    FR_COUNT_BOUNCE(bounce);
    /* Mirror bounces have budgets of their own (frame_constants.h). */
    const int max_steps = bounce == 0 ? fc->max_steps : fc->bounce_max_steps;
    const int shadow_steps = bounce == 0 ? fc->shadow_max_steps : fc->bounce_shadow_max_steps;
    march_result_t m = march(ray, path_t, bounce == 0 ? cone_from : (real_t)0,
                             (real_t)FR_SCALAR_MAX, max_steps, (real_t)1, fc,
                             params FR_COUNTS_ARG);
    if (bounce == 0) m.ao_steps += cone_ao;
    const mask_t hit = active & m.hit;
    const mask_t miss = active & !m.hit & !m.inside;
    vec3_t segment = FR_SKY(ray.dir);
    FR_APPLY_GLOW(segment, m, miss);
    real_t reflectivity = (real_t)0;
    vec3_t p = v3_mad(ray.origin, ray.dir, m.t);
    vec3_t n = v3_neg(ray.dir);
    real_t h = (real_t)0;
    if (any_lane(hit)) {
      h = hit_threshold(fc, path_t + m.t, p);
      /* Normals at the scale of the pixel's footprint (half of it), not of the hit threshold: a
       * fractal's normal depends on the scale it is taken at, and a smaller threshold (more
       * accuracy) must not turn the shading into sub-pixel noise. */
      const real_t normal_h = fmax(h, (real_t)(0.5f * fc->pixel_angle_rad) * (path_t + m.t));
      vec3_t gradient = calc_normal(p, normal_h, params);
      FR_COUNT(FR_COUNT_NORMALS, hit, FR_NORMAL_EVALS);
      /* A degenerate normal (all samples equal) faces the viewer. */
      n = v3_select(v3_length2(gradient) > (real_t)0, gradient, n);
      surface_t surface = surface_at(p);
      FR_COUNT(FR_COUNT_SURFACE, hit, FR_HAS_SURFACE);
      real_t ao = (real_t)1;
      FR_APPLY_AO(ao, p, n, m);
      FR_COUNT(FR_COUNT_AO, hit, FR_AO_EVALS);
      real_t shadow = (real_t)1;
      vec3_t lit = shade_surface(p, n, ray.dir, surface, ao, h, hit, shadow_steps, fc, params,
                                 &shadow FR_COUNTS_ARG);
      FR_APPLY_FOG(lit, path_t + m.t);
      segment = v3_select(hit, lit, segment);
      reflectivity = lane_select(hit, clamp(surface.reflectivity, (real_t)0, (real_t)1), 0);
      if (bounce == 0) {
        first_normal = v3_select(hit, v3_normalize(n), first_normal);
        first_albedo = v3_select(hit, surface.albedo, first_albedo);
        first_ao = lane_select(hit, ao, 1);
        first_shadow = lane_select(hit, shadow, 1);
      }
    }
    /* Inside the solid: black (march.cl). */
    segment = v3_select(active & m.inside, v3s(0, 0, 0), segment);
    if (bounce == 0) {
      first_depth = lane_select(m.hit | m.inside, path_t + m.t, INFINITY);
      first_steps = m.steps;
      first_status = lane_select(m.inside, FR_RAY_INSIDE,
                                 lane_select(m.out_of_steps, FR_RAY_OUT_OF_STEPS,
                                             lane_select(m.hit, FR_RAY_HIT, FR_RAY_MISS)));
    }
    /* What is not mirrored is this segment's own colour; at the last bounce, all of it. */
    const real_t own = bounce == bounces ? (real_t)1 : (real_t)1 - reflectivity;
    const real_t weight = lane_select(active, own, 0);
    color = v3_add(color, v3_scale(v3_mul(throughput, segment), weight));
    active = hit & (reflectivity > (real_t)0);
    if (bounce == bounces || !any_lane(active)) break;
    throughput = v3_scale(throughput, reflectivity);
    path_t += m.t;
    FR_BOUNCE(ray, p, n, h);
  }

  FR_COUNTS_END(counts_out);

  pixel_passes_t out;
  out.color = color;
  out.depth = first_depth;
  out.steps = first_steps;
  out.status = first_status;
  out.ao = first_ao;
  out.shadow = first_shadow;
  out.normal = first_normal;
  out.albedo = first_albedo;
  film_write(tile_x, tile_y, out, fc, hdr_rgba, depth, steps_out, factors_out, status_out,
             normal_out, albedo_out);
}
