// The display transform of kernels/post.cl in double, from its formulas (exposure, Narkowicz's
// ACES filmic fit, the sRGB curve), for the tests that check the kernel against it
// (post_test.cpp on rendered frames, ported_opencl_test.cpp on a ramp, also under Wine).
#pragma once

#include <algorithm>
#include <cmath>

namespace fr::test {

inline double aces(double x) {
  const double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

inline double srgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}

// The 8-bit level a linear value shows as.
inline int display_level(double linear, double exposure) {
  return static_cast<int>(
      std::clamp(std::floor(srgb(aces(linear * exposure)) * 255 + 0.5), 0.0, 255.0));
}

}  // namespace fr::test
