// bench_report.hpp — the benchmark's result as text for people and JSON for tools.
#pragma once

#include "bench/frame_stats.hpp"
#include "bench/system_info.hpp"
#include "render/eval_counts.hpp"

#include <string>

namespace fr {

struct BenchReport {
  std::string scene_id;
  std::string scene_version;
  int width_px = 0, height_px = 0;
  int lanes = 0;
  std::string precision;
  std::string stages;      // effects compiled in
  std::string integrator;  // "fast" or "path" (render.integrator)
  int samples_per_frame = 1;
  int runs = 0;
  int frames_per_run = 0;
  double path_duration_s = 0;  // scene time each run covers
  std::string camera_path;     // the path file flown; empty: the scene's own animation
  double wall_s = 0;           // real time of all timed frames
  double kernel_build_ms = 0;  // untimed warm-up frame, including the kernel build
  FrameStats stats;
  std::vector<double> run_mean_ms;  // one per run
  // DE evaluations of one counted pass over the same frames (untimed; counting kernels are
  // slower); samples == 0: not counted.
  EvalCounts counts;
  SystemInfo system;
};

// Pixel samples a second at the median frame time: what an integrator delivers.
double samples_per_second(const BenchReport& report);
std::string format_bench_text(const BenchReport& report);
std::string format_bench_json(const BenchReport& report);

}  // namespace fr
