#include "app/sample_bands.hpp"

#include <algorithm>
#include <cmath>

namespace fr {

SampleBand SampleBands::next(int sample_index, int height_px) {
  if (sample_index != sample_ || height_px != height_px_ || next_row_ >= height_px_) {
    sample_ = sample_index;
    height_px_ = height_px;
    next_row_ = 0;
  }
  SampleBand band;
  band.rows.first_row_px = next_row_;
  band.rows.rows_px = std::min(rows_, height_px_ - next_row_);
  next_row_ += band.rows.rows_px;
  band.last = next_row_ >= height_px_;
  return band;
}

void SampleBands::measured(int rows, double ms, bool at_most) {
  if (rows <= 0 || !(ms > 0) || !std::isfinite(ms)) return;
  const double wanted = rows * target_ms_ / ms;
  if (at_most && wanted < rows_) return;
  const double moved = std::clamp(wanted, 0.5 * rows_, 2.0 * rows_);
  // Whole multiples of the alignment (a band's rows must be one), at least one.
  const int aligned = static_cast<int>(std::lround(moved / kRowBandAlign)) * kRowBandAlign;
  rows_ = std::clamp(aligned, kRowBandAlign, kMaxRows);
}

}  // namespace fr
