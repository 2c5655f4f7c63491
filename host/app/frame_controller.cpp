#include "app/frame_controller.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace fr {

namespace {

// The lattice whose share of the pixels (1 / (stride_x * stride_y)) is the largest not above
// `share` (give or take 5%: the share approaches a value geometrically and never quite reaches
// it), strides at most one apart (so the lattice is about as fine across as down).
std::pair<int, int> lattice_strides(double share, int max_stride) {
  int best_x = max_stride, best_y = max_stride;
  for (int sy = 1; sy <= max_stride; ++sy)
    for (int sx = sy; sx <= std::min(sy + 1, max_stride); ++sx) {
      const double s = 1.0 / (sx * sy);
      if (s <= share * 1.05 && s > 1.0 / (best_x * best_y)) {
        best_x = sx;
        best_y = sy;
      }
    }
  return {best_x, best_y};
}

}  // namespace

FramePlan FrameController::plan(bool changed, bool reuse) {
  FramePlan p;
  if (changed) {
    moving_ = true;
    next_sample_ = 0;
    p.resolution_scale = reuse ? 1 : moving_scale_;
    p.step_budget = settings_.moving_step_budget;
    p.sample_index = 0;
    if (reuse) {
      p.lattice = true;
      std::tie(p.stride_x, p.stride_y) =
          lattice_strides(moving_share_, std::max(1, settings_.max_stride));
      if (settings_.fixed_stride_x > 0 && settings_.fixed_stride_y > 0) {
        p.stride_x = settings_.fixed_stride_x;
        p.stride_y = settings_.fixed_stride_y;
      }
    }
  } else {
    // Still: full resolution, restarting the accumulation the first time.
    if (moving_) {
      moving_ = false;
      next_sample_ = 0;
    }
    p.resolution_scale = 1;
    p.still = true;
    p.sample_index = next_sample_;
    p.done = next_sample_ >= settings_.full_quality_samples;
    if (!p.done) ++next_sample_;
  }
  last_ = p;
  return p;
}

void FrameController::report(double render_ms) {
  if (!moving_ || last_.sample_index != 0 || render_ms <= 0) return;
  const double ratio = settings_.target_frame_ms / render_ms;
  if (last_.lattice) {
    // The time is about proportional to the pixels traced: the share that would have met the
    // target, approached part of the way (the lattices are steps apart; this keeps the choice
    // from flickering between two of them).
    const double used = 1.0 / (last_.stride_x * last_.stride_y);
    const double wanted = used * std::clamp(ratio, 0.5, 2.0);
    const int m = std::max(1, settings_.max_stride);
    moving_share_ =
        std::clamp(std::pow(moving_share_, 0.7) * std::pow(wanted, 0.3), 1.0 / (m * m), 1.0);
    return;
  }
  // Pixels scale with the square of the resolution scale; move part of the way each frame.
  const double factor = std::clamp(std::sqrt(ratio), 0.8, 1.25);
  moving_scale_ = std::clamp(moving_scale_ * factor, settings_.min_scale, 1.0);
}

}  // namespace fr
