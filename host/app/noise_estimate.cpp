#include "app/noise_estimate.hpp"

#include <cmath>

namespace fr {

std::optional<NoiseEstimate> estimate_noise(const float* before, const float* after, size_t pixels,
                                            int n) {
  if (n < 2 || pixels == 0 || !before || !after) return std::nullopt;
  double step2 = 0, sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) {
      const double a = before[4 * i + c], b = after[4 * i + c];
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      step2 += (b - a) * (b - a);
      sum += b;
      ++count;
    }
  if (count == 0) return std::nullopt;
  NoiseEstimate e;
  e.standard_error = std::sqrt(step2 / static_cast<double>(count)) * std::sqrt(n - 1.0);
  e.mean = sum / static_cast<double>(count);
  return e;
}

}  // namespace fr
