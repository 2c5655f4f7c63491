/* post.cl — linear HDR to display: exposure, ACES filmic curve (Narkowicz's fit), sRGB encoding.
 * Each work-item converts four RGBA pixels as one float16, so the CPU path runs 16 wide without
 * relying on the OpenCL compiler to vectorise across work-items. */

inline float16 aces_filmic(float16 x) {
  const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

inline float16 srgb_encode(float16 linear) {
  float16 curve = 1.055f * exp2(log2(fmax(linear, 1e-8f)) * (1.0f / 2.4f)) - 0.055f;
  return select(curve, 12.92f * linear, linear <= 0.0031308f);
}

/* hdr_rgba and rgba8 hold 4 * quad_count pixels (the host pads the buffers to whole quads). */
__kernel void fr_post(__global const float* hdr_rgba, __global uchar* rgba8, float exposure,
                      int quad_count) {
  int i = get_global_id(0);
  if (i >= quad_count) return;
  float16 hdr = vload16(i, hdr_rgba);
  float16 display = srgb_encode(aces_filmic(hdr * exposure)) * 255.0f + 0.5f;
  const int16 is_alpha = (int16)(0, 0, 0, -1, 0, 0, 0, -1, 0, 0, 0, -1, 0, 0, 0, -1);
  display = select(display, (float16)255.0f, is_alpha);
  vstore16(convert_uchar16_sat(display), i, rgba8);
}
