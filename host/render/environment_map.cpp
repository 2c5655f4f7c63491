#include "render/environment_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fr {

std::vector<float> environment_buffer(const EnvironmentImage& image) {
  const size_t w = static_cast<size_t>(image.width_px), h = static_cast<size_t>(image.height_px);
  const size_t patch_rows = h + 1;
  std::vector<float> out(3 * w * h + (patch_rows + 1) + patch_rows * (w + 1));
  std::copy(image.rgb.begin(), image.rgb.end(), out.begin());
  float* rows = out.data() + 3 * w * h;
  float* columns = rows + patch_rows + 1;
  std::vector<double> luminance(w * h);
  double brightest = 0;
  for (size_t i = 0; i < w * h; ++i) {
    luminance[i] =
        0.2126 * image.rgb[3 * i] + 0.7152 * image.rgb[3 * i + 1] + 0.0722 * image.rgb[3 * i + 2];
    brightest = std::max(brightest, luminance[i]);
  }
  // A black panorama: every patch by its solid angle alone (it sends nothing wherever it is drawn;
  // the kernel's density is then uniform in each patch too).
  const bool black = !(brightest > 0);
  // Sums in double: an 8192-wide row of small weights beside a sun loses nothing.
  std::vector<double> row_weight(patch_rows), cumulative(w + 1);
  double total = 0;
  for (size_t pr = 0; pr < patch_rows; ++pr) {
    const size_t r0 = pr == 0 ? 0 : pr - 1, r1 = std::min(pr, h - 1);
    // The patch's extent in v (pixel rows) and the polar angle at its centre.
    const bool half = pr == 0 || pr == h;
    const double v_centre = pr == 0 ? 0.25 : (pr == h ? h - 0.25 : static_cast<double>(pr));
    const double sin_theta = std::sin(v_centre * std::numbers::pi / static_cast<double>(h));
    const double area = half ? 0.5 : 1.0;
    cumulative[0] = 0;
    for (size_t pc = 0; pc < w; ++pc) {
      const size_t c1 = (pc + 1) % w;
      const double mean = black ? 1.0
                                : 0.25 * (luminance[r0 * w + pc] + luminance[r0 * w + c1] +
                                          luminance[r1 * w + pc] + luminance[r1 * w + c1]);
      cumulative[pc + 1] = cumulative[pc] + mean * sin_theta * area;
    }
    row_weight[pr] = cumulative[w];
    total += cumulative[w];
    float* row = columns + (w + 1) * pr;
    for (size_t pc = 0; pc <= w; ++pc)
      row[pc] = cumulative[w] > 0 ? static_cast<float>(cumulative[pc] / cumulative[w])
                                  : static_cast<float>(static_cast<double>(pc) / w);
    row[w] = 1.0f;
  }
  double running = 0;
  rows[0] = 0.0f;
  for (size_t pr = 0; pr < patch_rows; ++pr) {
    running += row_weight[pr];
    rows[pr + 1] = static_cast<float>(running / total);
  }
  rows[patch_rows] = 1.0f;
  return out;
}

}  // namespace fr
