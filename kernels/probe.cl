/* probe.cl — evaluates the scene's DE at given points, FR_LANES points per work-item, through the
 * same prelude and parameter block as the renderer. Used by tests (DE values against analytic
 * ones) and by the host wherever it needs a distance without a second copy of the DE in C++. */

__kernel void fr_probe_de(__constant const scene_params_t* params, __global const float* xyz,
                          __global float* distance, int count) {
  const int first = get_global_id(0) * FR_LANES;
  float x[FR_LANES], y[FR_LANES], z[FR_LANES], d[FR_LANES];
  for (int lane = 0; lane < FR_LANES; ++lane) {
    int i = min(first + lane, count - 1); /* a partial last packet repeats the last point */
    x[lane] = xyz[3 * i + 0];
    y[lane] = xyz[3 * i + 1];
    z[lane] = xyz[3 * i + 2];
  }
  real_t de = scene_de(v3(load_lanes(x), load_lanes(y), load_lanes(z)), params);
  store_lanes(de, d);
  for (int lane = 0; lane < FR_LANES && first + lane < count; ++lane) distance[first + lane] = d[lane];
}
