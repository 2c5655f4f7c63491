/* cone.cl — the cone pre-pass (as in Marble Marcher CE's multi-resolution marching and cone
 * marching): one cone per block of FR_CONE_BLOCK x FR_CONE_BLOCK pixels marches from the start
 * of the block's rays until the surface comes near the cone; every primary ray of the block then
 * starts where its cone stopped instead of at its own origin, which skips the empty space in
 * front of the scene once per block instead of once per packet.
 *
 * Why it is safe: within the block, rays at the same parameter t lie within
 * r(t) = spread_origin + spread_dir * t of the cone's centre ray (measured at the block's corners,
 * jitter included, with a margin), so where the DE at the centre point is D > r(t), the ball of
 * radius D around it is empty and contains every block ray's point at t with room D - r(t) ahead:
 * all of them may advance by D - r(t). The DE must be a lower bound there (the march assumes the
 * same); the cone never relaxes. Nothing is skipped for a camera inside or on the surface (the
 * first D is below 2 r), and the pass is off with depth of field (the lens moves every ray).
 *
 * Step-count AO counts the plain sphere-tracing steps a ray needs before it comes near the
 * surface (march.cl); the cone's share is estimated as the sum of dt / D over its steps (what
 * plain sphere tracing would have spent over the same stretch) and handed to each ray, so
 * occlusion does not change with the pre-pass. */

/* How far apart two block rays at the same t can be: |origin difference| + |direction
 * difference| t, the largest over the block's corners: half a pixel beyond where a jittered
 * sample of the block's pixels can go. */
inline void cone_spread(__constant const fr_frame_constants* fc, ray_t centre, real_t bx,
                        real_t by, real_t* spread_origin, real_t* spread_dir) {
  real_t so = (real_t)0, sd = (real_t)0;
  for (int corner = 0; corner < 4; ++corner) {
    const real_t cx = bx + (real_t)((corner & 1) ? FR_CONE_BLOCK : -1);
    const real_t cy = by + (real_t)((corner & 2) ? FR_CONE_BLOCK : -1);
    real_t unused;
    const ray_t r = camera_ray(fc, cx, cy, (real_t)0, (real_t)0, &unused);
    so = fmax(so, v3_length(v3_sub(r.origin, centre.origin)));
    sd = fmax(sd, v3_length(v3_sub(r.dir, centre.dir)));
  }
  /* The corners bound a ray field that is nearly linear in the pixel offsets; the margin covers
   * the rest (normalisation, wide fields of view). */
  *spread_origin = so * (real_t)1.25;
  *spread_dir = sd * (real_t)1.25;
}

/* One cone per lane; a work-item's lanes are FR_TILE_W x FR_TILE_H neighbouring blocks. Writes,
 * per block, the parameter t where its rays may start (0, their own entry into the bounds, when
 * the cone could not skip anything; -1 when it found nothing to hit) and the AO steps the
 * skipped stretch stands for. No block ray hits the surface before its block's t: the host
 * judges a view's precision by the least (Renderer::choose_precision). */
__kernel void fr_cone(__constant const fr_frame_constants* fc,
                      __constant const scene_params_t* params, __global float* cone_t_out,
                      __global float* cone_ao_steps_out, __global uint* counts_out) {
  FR_COUNTS_BEGIN;
  const real_t block_x = (real_t)(get_global_id(0) * FR_TILE_W) + FR_LANE_X;
  const real_t block_y = (real_t)(get_global_id(1) * FR_TILE_H) + FR_LANE_Y;
  /* The block's first pixel, in this image's (or window's) pixel coordinates. */
  const real_t bx = block_x * (real_t)FR_CONE_BLOCK - (real_t)fc->cone_phase_x;
  const real_t by = block_y * (real_t)FR_CONE_BLOCK - (real_t)fc->cone_phase_y;
  const real_t to_centre = (real_t)(0.5f * (FR_CONE_BLOCK - 1));
  real_t path_t;
  const ray_t ray = camera_ray(fc, bx + to_centre, by + to_centre, (real_t)0, (real_t)0, &path_t);
  real_t spread_origin, spread_dir;
  cone_spread(fc, ray, bx, by, &spread_origin, &spread_dir);

  /* The block's rays may enter the bounds before the centre ray does: the cone starts where it
   * touches them, at the centre ray's entry into the bounds grown by the spread (at a t no
   * smaller than any where the ray is inside them). Before that, every block ray is outside the
   * bounds, where there is no surface. */
  const scalar_t radius = fc->bounding_radius;
  const vec3_t origin = FR_FROM_CENTRE(ray.origin);
  const real_t grown =
      (real_t)radius + spread_origin + spread_dir * (v3_length(origin) + (real_t)(3 * radius));
  const real_t b = v3_dot(origin, ray.dir);
  const real_t disc = b * b - (v3_length2(origin) - grown * grown);
  const real_t root = sqrt(fmax(disc, (real_t)0));
  real_t t = fmax(-b - root, (real_t)0);
  const real_t t_exit = -b + root;
  const mask_t in_bounds = (disc > (real_t)0) & (t_exit > (real_t)0);
  mask_t active = in_bounds & (block_x < (real_t)fc->cone_blocks_x) &
                  (block_y < (real_t)fc->cone_blocks_y);
  real_t ao_steps = (real_t)0;
  for (int i = 0; i < fc->max_steps && any_lane(active); ++i) {
    const vec3_t p = v3_mad(ray.origin, ray.dir, t);
    /* Outside the bounds the distance to them is exact, and the DE may over-estimate there
     * (march.cl never evaluates it outside). */
    const real_t outside = v3_length(FR_FROM_CENTRE(p)) - (real_t)radius;
    const real_t dist = lane_select(outside > (real_t)0, outside,
                                    scene_de(p, params) * (real_t)fc->step_scale);
    FR_COUNT(FR_COUNT_CONE, active, 1);
    const real_t r = spread_origin + spread_dir * t;
    /* Near the surface (or inside it, or on it at the eye: a few hit thresholds) the cone ends
     * and the rays do the rest, with march.cl's rules for rays that start on a surface. */
    active &= dist > (real_t)2 * r + (real_t)4 * hit_threshold(fc, path_t + t, p);
    const real_t advance = dist - r;
    /* The rays themselves march only inside the bounds. */
    ao_steps = lane_select(active & (outside <= (real_t)0), ao_steps + advance / dist, ao_steps);
    t = lane_select(active, fmin(t + advance, t_exit), t);
    active &= t < t_exit;
  }
  /* Where the cone left the bounds (or never met them), no block ray can hit: -1, and the rays
   * find out for themselves (march.cl starts them at their own entry into the bounds, as for 0;
   * the host reads -1 as "nothing to hit", Renderer::cone_hit_bound). */
  t = lane_select(in_bounds & (t < t_exit), t, -1);

  float tt[FR_LANES], aa[FR_LANES], bxs[FR_LANES], bys[FR_LANES];
  store_lanes(t, tt);
  store_lanes(ao_steps, aa);
  store_lanes(block_x, bxs);
  store_lanes(block_y, bys);
  for (int lane = 0; lane < FR_LANES; ++lane) {
    const int x = (int)bxs[lane], y = (int)bys[lane];
    if (x >= fc->cone_blocks_x || y >= fc->cone_blocks_y) continue;
    cone_t_out[y * fc->cone_blocks_x + x] = tt[lane];
    cone_ao_steps_out[y * fc->cone_blocks_x + x] = aa[lane];
  }
  FR_COUNTS_END(counts_out);
}

/* Where the primary rays of the tile at (tile_x, tile_y) start, and the AO steps the cone saved
 * them: each lane reads its own pixel's block. */
inline void cone_start(__constant const fr_frame_constants* fc, __global const float* cone_t,
                       __global const float* cone_ao_steps, int tile_x, int tile_y, real_t* t,
                       real_t* ao_steps) {
  float tt[FR_LANES], aa[FR_LANES];
  for (int lane = 0; lane < FR_LANES; ++lane) {
    const int x = min((tile_x + lane % FR_TILE_W + fc->cone_phase_x) / FR_CONE_BLOCK,
                      fc->cone_blocks_x - 1);
    const int y = min((tile_y + lane / FR_TILE_W + fc->cone_phase_y) / FR_CONE_BLOCK,
                      fc->cone_blocks_y - 1);
    tt[lane] = cone_t[y * fc->cone_blocks_x + x];
    aa[lane] = cone_ao_steps[y * fc->cone_blocks_x + x];
  }
  *t = load_lanes(tt);
  *ao_steps = load_lanes(aa);
}

#define FR_CONE_START(t, ao_steps) \
  cone_start(fc, cone_t, cone_ao_steps, tile_x, tile_y, &(t), &(ao_steps))
