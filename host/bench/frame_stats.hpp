// frame_stats.hpp — frame-time statistics, and the timing loop that collects them on any clock
// (the benchmark passes a steady clock; tests pass a scripted one).
#pragma once

#include <functional>
#include <vector>

namespace fr {

struct FrameStats {
  size_t frames = 0;
  double total_ms = 0;  // sum of frame times
  double min_ms = 0, max_ms = 0, mean_ms = 0;
  double p50_ms = 0, p95_ms = 0;    // nearest-rank percentiles
  double mean_fps = 0;              // 1000 / mean_ms: frames per second over the whole run
  double min_fps = 0, max_fps = 0;  // 1000 / max_ms and 1000 / min_ms
};

// Nearest-rank percentile: the smallest value with at least `percent` (0 to 100) of `values` at
// or below it; 0 for no values. The one percentile of frame times (bench) and of pixel errors
// (sweep).
double percentile(std::vector<double> values, double percent);

// Statistics of `frame_ms` (at least one frame).
FrameStats summarize_frames(std::vector<double> frame_ms);

// Times `count` calls of render_frame(i), i = 0 .. count-1, with `now_ms`.
std::vector<double> time_frames(int count, const std::function<void(int)>& render_frame,
                                const std::function<double()>& now_ms);

}  // namespace fr
