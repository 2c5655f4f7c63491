// sample_bands.hpp — a parked view's path-traced sample rendered in bands of rows, each about a
// frame's time, so that the explorer reads input and redraws between them: a whole 1280x720
// sample of the Mandelbulb takes about half a second on the 2-core machine, and held the explorer
// that long. Each pixel gets the same sample either way (render_settings.hpp, RowBand).
//
// The band's height follows the time measured for the bands before it; the first band of a
// refinement has kInitialRows rows.
#pragma once

#include "render/render_settings.hpp"

namespace fr {

struct SampleBand {
  RowBand rows;
  bool last = false;  // ends the sample: the frame is read back and shown
};

class SampleBands {
 public:
  static constexpr int kInitialRows = 4 * kRowBandAlign;
  static constexpr int kMaxRows = 1 << 16;  // taller than any image (the doubling stops)

  explicit SampleBands(double target_ms) : target_ms_(target_ms) {}

  // The next band of sample `sample_index` of an image `height_px` rows tall: the sample's first
  // when another sample (or another height) was under way, or the last one was ended.
  SampleBand next(int sample_index, int height_px);
  // `rows` rows took `ms` to render (`at_most`: no longer than `ms`, which then only lets the
  // bands grow): later bands aim at the target time, moving at most a factor of 2 a measurement
  // so that one slow frame does not swing them.
  void measured(int rows, double ms, bool at_most = false);
  // No sample under way: the next band starts one (the view changed).
  void reset() { sample_ = -1; }

  int rows_per_band() const { return rows_; }

 private:
  double target_ms_;
  int rows_ = kInitialRows;
  int sample_ = -1;
  int height_px_ = 0;
  int next_row_ = 0;
};

}  // namespace fr
