// noise_estimate.hpp — how much noise is left in a progressive accumulation (the explorer's
// parked path-traced view), from the running means before and after its latest sample, without
// keeping every pixel's variance.
//
// Each pixel's mean after n samples is m_n = m_(n-1) + (x_n - m_(n-1)) / n. With the samples
// independent and of standard deviation sigma, x_n - m_(n-1) has variance sigma^2 n / (n - 1), so
// the step's mean square over the pixels estimates sigma^2 / (n (n - 1)), and the mean's standard
// error sigma / sqrt(n) is sqrt(n - 1) times the steps' RMS. Pixels whose noise differs pool into
// the image's RMS standard error. One sample's step is itself noisy: the estimate of one frame
// scatters by about 1 / sqrt(2 x pixels) relative (0.07% at 1280x720).
#pragma once

#include <cstddef>
#include <optional>

namespace fr {

struct NoiseEstimate {
  double standard_error = 0;  // RMS over the pixels' channels of the mean's standard error
  double mean = 0;            // the mean of the pixels' channels (linear), for a relative figure
  double relative() const { return mean > 0 ? standard_error / mean : 0; }
};

// `before` and `after`: the linear RGBA means (4 floats a pixel, alpha ignored) of `pixels`
// pixels before and after the n-th sample (n >= 2; nothing below that, or without pixels).
// Pixels that are not finite in either are left out.
std::optional<NoiseEstimate> estimate_noise(const float* before, const float* after, size_t pixels,
                                            int n);

}  // namespace fr
