// frame_controller.hpp — holding a frame rate while the view changes, and refining once it stops.
//
// While the camera or parameters change, each frame renders one sample at a resolution scale
// that the controller adjusts towards the target frame time (the sub-image
// rendering: a smaller image, shown scaled up) and with a reduced step budget. Once nothing
// changes, the scale goes to 1 and further frames accumulate jittered samples into the same image
// until `full_quality_samples` is reached.
#pragma once

namespace fr {

struct FrameControllerSettings {
  double target_frame_ms = 1000.0 / 30.0;
  double min_scale = 0.25;          // of the window's width and height
  double moving_step_budget = 0.6;  // fraction of the march steps used while moving
  int full_quality_samples = 8;
};

struct FramePlan {
  double resolution_scale = 1;  // render at window size x this
  double step_budget = 1;       // fraction of the settings' max_steps to march
  int sample_index = 0;         // 0 starts a new accumulation
  bool done = false;            // full quality reached: nothing left to render
};

class FrameController {
 public:
  explicit FrameController(FrameControllerSettings settings = {}) : settings_(settings) {}

  // What to render this frame; `changed` says whether the view or scene changed since the last.
  FramePlan plan(bool changed);
  // How long the render of the last plan took.
  void report(double render_ms);

  double scale() const { return moving_scale_; }
  const FrameControllerSettings& settings() const { return settings_; }

 private:
  FrameControllerSettings settings_;
  double moving_scale_ = 0.5;
  bool moving_ = true;
  int next_sample_ = 0;
  FramePlan last_;
};

}  // namespace fr
