/* render.cl — the frame kernel: one work-item per tile of FR_TILE_W x FR_TILE_H pixels (one
 * pixel at FR_LANES 1). Rays -> march -> normals -> shadow/AO -> shade; writes linear HDR RGBA,
 * hit depth (+inf for a miss) and DE steps per pixel. The host pastes the optional stages
 * (shadow.cl, ao.cl) in only when the scene needs them and they are switched on. */

/* Stage hooks: a stage file that is compiled in defines its hook; otherwise the hook does nothing
 * and none of the stage's code is in the kernel. */
#ifndef FR_APPLY_SHADOWS
#define FR_APPLY_SHADOWS(shadow, p, n, h, m)
#endif
#ifndef FR_APPLY_AO
#define FR_APPLY_AO(ao, m)
#endif

__kernel void fr_render(__constant const fr_frame_constants* fc,
                        __constant const scene_params_t* params, __global float* hdr_rgba,
                        __global float* depth, __global float* steps_out) {
  const int tile_x = get_global_id(0) * FR_TILE_W;
  const int tile_y = get_global_id(1) * FR_TILE_H;
  real_t px = (real_t)tile_x + FR_LANE_X;
  real_t py = (real_t)tile_y + FR_LANE_Y;

  ray_t ray = camera_ray(fc, px, py);
  march_result_t m = march(ray, fc, params);
  vec3_t color = sky_color(ray.dir, fc);
  real_t t_hit = lane_select(m.hit, m.t, INFINITY);

  if (any_lane(m.hit)) {
    vec3_t p = v3_mad(ray.origin, ray.dir, m.t);
    real_t h = hit_threshold(fc, m.t, p);
    vec3_t n = calc_normal(p, h, params);
    /* A degenerate normal (all four samples equal) faces the viewer. */
    n = v3_select(v3_length2(n) > (real_t)0, n, v3_neg(ray.dir));
    real_t shadow = (real_t)1;
    real_t ao = (real_t)1;
    FR_APPLY_SHADOWS(shadow, p, n, h, m);
    FR_APPLY_AO(ao, m);
    color = v3_select(m.hit, shade_surface(n, ray.dir, shadow, ao, fc), color);
  }

  /* Scatter the lanes to their pixels; tiles at the right and bottom edges are partial. */
  float r[FR_LANES], g[FR_LANES], b[FR_LANES], d[FR_LANES], s[FR_LANES];
  store_lanes(color.x, r);
  store_lanes(color.y, g);
  store_lanes(color.z, b);
  store_lanes(t_hit, d);
  store_lanes(m.steps, s);
  for (int lane = 0; lane < FR_LANES; ++lane) {
    int x = tile_x + lane % FR_TILE_W;
    int y = tile_y + lane / FR_TILE_W;
    if (x >= fc->width || y >= fc->height) continue;
    int i = y * fc->width + x;
    hdr_rgba[4 * i + 0] = r[lane];
    hdr_rgba[4 * i + 1] = g[lane];
    hdr_rgba[4 * i + 2] = b[lane];
    hdr_rgba[4 * i + 3] = 1.0f;
    depth[i] = d[lane];
    steps_out[i] = s[lane];
  }
}
