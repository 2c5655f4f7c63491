// explore_bench.hpp — the explorer's interactivity measured: a scripted fly-through (a fixed
// path of key presses and mouse turns) at a given window size, frames timed while moving, then
// the time from stopping until the image reaches full quality. Headless: everything the
// explorer does per frame except drawing to a window.
#pragma once

#include "app/explorer.hpp"
#include "bench/frame_stats.hpp"

namespace fr {

struct ExploreBenchResult {
  FrameStats moving;  // frames while the camera moves
  double mean_resolution_scale = 0;
  double seconds_to_full_resolution = 0;  // after the camera stops: first full-size sample shown
  double seconds_to_full_quality = 0;     // ... and all anti-aliasing samples
  int refine_frames = 0;
  // With the explorer counting (Explorer::set_count_evaluations): the moving frames' DE
  // evaluations, per pixel over all their pixels.
  EvalCounts moving_counts;
};

// Flies for `moving_frames` frames (forward, weaving left and right; each frame moves the camera
// by 1/30 s of flight, so the path does not depend on the machine's speed), then stops and renders until
// the frame controller reports full quality.
ExploreBenchResult run_explore_bench(Explorer& explorer, int window_width_px, int window_height_px,
                                     int moving_frames);

}  // namespace fr
