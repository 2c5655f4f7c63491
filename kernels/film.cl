/* film.cl — where a work-item's samples go: each lane's colour into the running mean in hdr_rgba
 * (progressive anti-aliasing, depth of field, path tracing) and, for the primary ray, the passes
 * the host will read (FR_OUTPUTS, renderer.hpp's Readback). Both integrators (render.cl, path.cl)
 * end with it. */

/* Both integrators' kernel, fr_render: the arguments the host sets (renderer.cpp), and the tile
 * of pixels each work-item renders, one per lane: (px, py) in this image's pixel coordinates. */
#define FR_RENDER_KERNEL_PARAMS                                                                  \
  __constant const fr_frame_constants *fc, __constant const scene_params_t *params,             \
      __global float *hdr_rgba, __global float *depth, __global float *steps_out,               \
      __global float *factors_out, __global uchar *status_out, __global float *normal_out,      \
      __global float *albedo_out, __global uint *counts_out, __global const float *cone_t,      \
      __global const float *cone_ao_steps, __global const float *environment
#define FR_RENDER_TILE                                   \
  const int tile_x = get_global_id(0) * FR_TILE_W;       \
  const int tile_y = get_global_id(1) * FR_TILE_H;       \
  const real_t px = (real_t)tile_x + FR_LANE_X;          \
  const real_t py = (real_t)tile_y + FR_LANE_Y

typedef struct pixel_passes_t {
  vec3_t color;  /* this sample's linear radiance */
  real_t depth;  /* the primary ray's: distance to the hit from the eye, +inf for a miss */
  real_t steps;  /* DE evaluations of the primary march */
  real_t status; /* FR_RAY_* (march.cl) */
  real_t ao;     /* occlusion and first-light shadow factors at the hit; 1 on a miss */
  real_t shadow;
  vec3_t normal; /* unit normal and albedo at the hit; 0 for a miss */
  vec3_t albedo;
} pixel_passes_t;

void film_write(int tile_x, int tile_y, pixel_passes_t v, __constant const fr_frame_constants* fc,
                __global float* hdr_rgba, __global float* depth, __global float* steps_out,
                __global float* factors_out, __global uchar* status_out,
                __global float* normal_out, __global float* albedo_out) {
  /* Scatter the lanes to their pixels; tiles at the right and bottom edges are partial. */
  float r[FR_LANES], g[FR_LANES], b[FR_LANES], d[FR_LANES], s[FR_LANES], o[FR_LANES],
      sh[FR_LANES], st[FR_LANES], nx[FR_LANES], ny[FR_LANES], nz[FR_LANES], ar[FR_LANES],
      ag[FR_LANES], ab[FR_LANES];
  store_lanes(v.color.x, r);
  store_lanes(v.color.y, g);
  store_lanes(v.color.z, b);
  store_lanes(v.depth, d);
  store_lanes(v.steps, s);
  store_lanes(v.ao, o);
  store_lanes(v.shadow, sh);
  store_lanes(v.status, st);
  store_lanes(v.normal.x, nx);
  store_lanes(v.normal.y, ny);
  store_lanes(v.normal.z, nz);
  store_lanes(v.albedo.x, ar);
  store_lanes(v.albedo.y, ag);
  store_lanes(v.albedo.z, ab);
  const float w = fc->accumulate_weight;
  for (int lane = 0; lane < FR_LANES; ++lane) {
    int x = tile_x + lane % FR_TILE_W;
    int y = tile_y + lane / FR_TILE_W;
    if (x >= fc->width || y >= fc->height) continue;
    int i = y * fc->width + x;
    if (w < 1.0f) { /* running mean; the first sample overwrites whatever was there */
      hdr_rgba[4 * i + 0] += (r[lane] - hdr_rgba[4 * i + 0]) * w;
      hdr_rgba[4 * i + 1] += (g[lane] - hdr_rgba[4 * i + 1]) * w;
      hdr_rgba[4 * i + 2] += (b[lane] - hdr_rgba[4 * i + 2]) * w;
    } else {
      hdr_rgba[4 * i + 0] = r[lane];
      hdr_rgba[4 * i + 1] = g[lane];
      hdr_rgba[4 * i + 2] = b[lane];
    }
    hdr_rgba[4 * i + 3] = 1.0f;
    /* The passes the host will read (FR_OUTPUTS, renderer.hpp's Readback); the rest are not
     * written at all. */
#if FR_OUTPUTS >= 1
    steps_out[i] = s[lane];
    status_out[i] = (uchar)st[lane];
#endif
#if FR_OUTPUTS >= 2
    depth[i] = d[lane];
    factors_out[2 * i + 0] = o[lane];
    factors_out[2 * i + 1] = sh[lane];
    normal_out[3 * i + 0] = nx[lane];
    normal_out[3 * i + 1] = ny[lane];
    normal_out[3 * i + 2] = nz[lane];
    albedo_out[3 * i + 0] = ar[lane];
    albedo_out[3 * i + 1] = ag[lane];
    albedo_out[3 * i + 2] = ab[lane];
#endif
  }
}
