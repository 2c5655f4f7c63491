/* denoise.cl — an edge-avoiding à-trous filter for path-traced pictures of few samples (Dammertz,
 * Sewtz, Hanika and Lensch 2010, "Edge-avoiding À-Trous wavelet transform for fast global
 * illumination filtering"): passes of a 5x5 B3-spline kernel whose taps lie `step` pixels apart
 * (1, 2, 4, 8, 16: a 61-pixel footprint in five passes of 25 taps), each tap weighted down where
 * the guides say it is another surface: its normal (the first hit's, noise-free), its depth
 * (relative to the pixel's footprint there), its albedo (texture edges), and its colour (relative
 * difference, looser each pass, which keeps lighting edges such as shadow boundaries).
 *
 * The colour is divided by the albedo before filtering and multiplied back after (the
 * illumination is smooth where the texture is not), so the filter blurs light, not detail.
 * Pixels that saw the sky (depth +inf) are filtered only with sky. Runs on the device between
 * the accumulation and post.cl, on the HDR running mean (float4 per pixel). Not lane-generic:
 * one work-item per pixel; the scene's code is not in this program. */

inline float3 load3(__global const float* a, int i) {
  return (float3)(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
}

/* Illumination: the colour over the albedo (where there is an albedo; the sky is its own). */
inline float3 demodulate(float3 color, float3 albedo) {
  return color / fmax(albedo, (float3)(0.02f));
}

/* One pass. `first`: `in` holds colour, which the pass demodulates; `last`: it writes colour
 * (remodulated), else illumination. */
__kernel void fr_denoise(__global const float4* in, __global float4* out,
                         __global const float* normal, __global const float* albedo,
                         __global const float* depth, int width, int height, int step,
                         float pixel_angle_rad, float color_sigma, int first, int last) {
  const int x = get_global_id(0), y = get_global_id(1);
  if (x >= width || y >= height) return;
  const int i = y * width + x;
  const float3 n_i = load3(normal, i), a_i = load3(albedo, i);
  const float z_i = depth[i];
  const int sky_i = !isfinite(z_i);
  float3 c_i = in[i].xyz;
  if (first && !sky_i) c_i = demodulate(c_i, a_i);
  const float kernel_weights[3] = {3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};
  /* A depth difference this large between neighbours `step` pixels apart is another surface:
   * a few footprints' worth, more at grazing angles (the normal's tilt from the view). */
  const float footprint = sky_i ? 1.0f : z_i * pixel_angle_rad * (float)step;
  float3 sum = (float3)(0.0f);
  float weight_sum = 0.0f;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int xj = clamp(x + dx * step, 0, width - 1), yj = clamp(y + dy * step, 0, height - 1);
      const int j = yj * width + xj;
      const float z_j = depth[j];
      const int sky_j = !isfinite(z_j);
      if (sky_i != sky_j) continue;
      float3 c_j = in[j].xyz;
      /* The edge-stopping terms add up in one exponent (one exp a tap: the filter's cost). */
      float w = kernel_weights[abs(dx)] * kernel_weights[abs(dy)];
      float exponent = 0.0f;
      if (!sky_i) {
        if (first) c_j = demodulate(c_j, load3(albedo, j));
        float facing = fmax(dot(n_i, load3(normal, j)), 0.0f); /* ^32 by five squarings */
        facing *= facing;
        facing *= facing;
        facing *= facing;
        facing *= facing;
        facing *= facing;
        w *= facing;
        exponent += fabs(z_i - z_j) / (8.0f * footprint);
        const float3 da = a_i - load3(albedo, j);
        exponent += dot(da, da) / 0.01f;
      }
      /* Relative colour difference, per channel's worst. */
      const float3 dc = fabs(c_i - c_j) / (fabs(c_i) + fabs(c_j) + (float3)(1e-3f));
      const float d = fmax(dc.x, fmax(dc.y, dc.z));
      exponent += d * d / (color_sigma * color_sigma);
      w *= native_exp(-exponent);
      sum += w * c_j;
      weight_sum += w;
    }
  float3 result = weight_sum > 0.0f ? sum / weight_sum : c_i;
  if (last && !sky_i) result *= fmax(a_i, (float3)(0.02f));
  out[i] = (float4)(result, 1.0f);
}
