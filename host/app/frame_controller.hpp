// frame_controller.hpp — holding a frame rate while the view changes, and refining once it stops.
//
// While the camera or parameters change, each frame renders one sample at a resolution scale
// that the controller adjusts towards the target frame time (the sub-image
// rendering: a smaller image, shown scaled up) and with a reduced step budget. Once nothing
// changes, the scale goes to 1 and further frames accumulate jittered samples into the same image
// until `full_quality_samples` is reached.
//
// With temporal reuse (app/temporal_reuse.hpp) a moving frame is traced at full resolution on a
// lattice of the window's pixels instead, the rest carried from earlier frames: the controller
// picks the lattice's strides (the share of pixels traced) towards the target frame time the same
// way. The caller says for each frame which of the two it can use (reuse falls back to the scaled
// frame when more than the camera changed).
#pragma once

namespace fr {

struct FrameControllerSettings {
  double target_frame_ms = 1000.0 / 30.0;
  double min_scale = 0.25;          // of the window's width and height
  double moving_step_budget = 0.6;  // fraction of the march steps used while moving
  int full_quality_samples = 8;
  int max_stride = 5;  // temporal reuse: at most every 5th column of every 5th row traced
  // Temporal reuse with this lattice whatever the frame time (a measurement's); 0: chosen.
  int fixed_stride_x = 0, fixed_stride_y = 0;
};

struct FramePlan {
  double resolution_scale = 1;  // render at window size x this
  double step_budget = 1;       // fraction of the settings' max_steps to march
  // Temporal reuse (resolution_scale 1): trace every stride_x-th column of every stride_y-th row.
  bool lattice = false;
  int stride_x = 1;
  int stride_y = 1;
  int sample_index = 0;  // 0 starts a new accumulation
  bool done = false;     // full quality reached: nothing left to render
  bool still = false;    // nothing changed: a sample of the parked view's accumulation
};

class FrameController {
 public:
  explicit FrameController(FrameControllerSettings settings = {}) : settings_(settings) {}

  // What to render this frame; `changed` says whether the view or scene changed since the last,
  // `reuse` whether a moving frame may be a lattice (temporal reuse) rather than scaled.
  FramePlan plan(bool changed, bool reuse = false);
  // How long the render of the last plan took.
  void report(double render_ms);
  // The last plan's sample was rendered only in part (a band of its rows: app/sample_bands.hpp):
  // the next still plan is the same sample.
  void sample_unfinished() {
    if (!moving_ && last_.still && !last_.done) next_sample_ = last_.sample_index;
  }

  double scale() const { return moving_scale_; }
  double lattice_share() const { return moving_share_; }  // wanted share of pixels traced
  const FrameControllerSettings& settings() const { return settings_; }
  // Samples a parked view accumulates (the explorer's, for the integrator in use); the refinement
  // under way goes on to the new count.
  void set_full_quality_samples(int samples) { settings_.full_quality_samples = samples; }
  void fix_lattice(int stride_x, int stride_y) {
    settings_.fixed_stride_x = stride_x;
    settings_.fixed_stride_y = stride_y;
  }

 private:
  FrameControllerSettings settings_;
  double moving_scale_ = 0.5;
  double moving_share_ = 0.25;
  bool moving_ = true;
  int next_sample_ = 0;
  FramePlan last_;
};

}  // namespace fr
