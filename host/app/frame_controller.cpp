#include "app/frame_controller.hpp"

#include <algorithm>
#include <cmath>

namespace fr {

FramePlan FrameController::plan(bool changed) {
  FramePlan p;
  if (changed) {
    moving_ = true;
    next_sample_ = 0;
    p.resolution_scale = moving_scale_;
    p.step_budget = settings_.moving_step_budget;
    p.sample_index = 0;
  } else {
    // Still: full resolution, restarting the accumulation the first time.
    if (moving_) {
      moving_ = false;
      next_sample_ = 0;
    }
    p.resolution_scale = 1;
    p.sample_index = next_sample_;
    p.done = next_sample_ >= settings_.full_quality_samples;
    if (!p.done) ++next_sample_;
  }
  last_ = p;
  return p;
}

void FrameController::report(double render_ms) {
  if (!moving_ || last_.sample_index != 0 || render_ms <= 0) return;
  // Pixels scale with the square of the resolution scale; move part of the way each frame.
  const double ratio = settings_.target_frame_ms / render_ms;
  const double factor = std::clamp(std::sqrt(ratio), 0.8, 1.25);
  moving_scale_ = std::clamp(moving_scale_ * factor, settings_.min_scale, 1.0);
}

}  // namespace fr
