/* post.cl — linear HDR to display: exposure, ACES filmic curve (Narkowicz's fit), sRGB encoding.
 * One pixel per work-item; this stage is cheap and needs no lanes. */

inline float aces_filmic(float x) {
  const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

inline float srgb_encode(float linear) {
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * pow(linear, 1.0f / 2.4f) - 0.055f;
}

__kernel void fr_post(__global const float* hdr_rgba, __global uchar* rgba8, float exposure,
                      int pixel_count) {
  int i = get_global_id(0);
  if (i >= pixel_count) return;
  for (int c = 0; c < 3; ++c) {
    float v = srgb_encode(aces_filmic(hdr_rgba[4 * i + c] * exposure));
    rgba8[4 * i + c] = (uchar)(v * 255.0f + 0.5f);
  }
  rgba8[4 * i + 3] = 255;
}
