// explore_bench.hpp — the explorer's interactivity measured: a scripted fly-through (a fixed
// path of key presses and mouse turns) at a given window size, frames timed while moving, then
// the time from stopping until the image reaches full quality. Headless: everything the
// explorer does per frame except drawing to a window. Optionally, what the user saw while moving
// judged against fully traced frames at the same cameras (image error, bench/image_error.hpp).
#pragma once

#include "app/explorer.hpp"
#include "bench/frame_stats.hpp"
#include "bench/image_error.hpp"

#include <string>

namespace fr {

// The moving frames as displayed (stretched to the window) against a full-resolution frame of
// the same camera and scene state with every step (the explorer's first sample once parked).
struct DisplayedError {
  int frames = 0;                      // moving frames judged
  double mean_mae = 0, max_mae = 0;    // mean absolute error, 0 to 1 (bench/image_error.hpp)
  double mean_ssim = 1, min_ssim = 1;  // structural similarity, 1 is identical
};

struct ExploreBenchResult {
  FrameStats moving;  // frames while the camera moves
  double mean_resolution_scale = 0;
  // Temporal reuse: the moving frames that used it, and their pixels per frame (means).
  int temporal_frames = 0;
  double mean_fresh_px = 0, mean_reused_px = 0, mean_rejected_px = 0, mean_filled_px = 0;
  // ... and the medians of their render's time (the lattice traced and read back) and of
  // carrying the rest (TemporalReuse::compose), ms.
  double median_trace_ms = 0, median_compose_ms = 0;
  double seconds_to_full_resolution = 0;  // after the camera stops: first full-size sample shown
  double seconds_to_full_quality = 0;     // ... and all anti-aliasing samples
  int refine_frames = 0;
  // The longest frame (update and render) while refining: how long input may wait then (a
  // path-traced sample renders in bands of about a frame's time: app/sample_bands.hpp).
  double refine_frame_max_ms = 0;
  // With the explorer counting (Explorer::set_count_evaluations): the moving frames' DE
  // evaluations, per pixel over all their pixels.
  EvalCounts moving_counts;
  DisplayedError moving_error;  // with measure_error
};

struct ExploreBenchOptions {
  int moving_frames = 120;
  // Keep each moving frame and its camera, and after the run (so that no timing includes it)
  // render the reference of each and compare.
  bool measure_error = false;
  // With measure_error: moving frame `save_frame` (0 first; -1 none) as shown and its reference,
  // written to save_prefix + "shown.png" and save_prefix + "reference.png" (what the user saw,
  // beside what full tracing gives: docs/performance.md's crops).
  int save_frame = -1;
  std::string save_prefix;
};

// Flies for `options.moving_frames` frames (forward, weaving left and right; each frame moves the
// camera by 1/30 s of flight, so the path does not depend on the machine's speed), then stops and
// renders until the frame controller reports full quality.
ExploreBenchResult run_explore_bench(Explorer& explorer, int window_width_px, int window_height_px,
                                     const ExploreBenchOptions& options);

}  // namespace fr
