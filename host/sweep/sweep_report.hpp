// sweep_report.hpp — a finished sweep as a terminal table, CSV, JSON and an SVG plot of error
// against frame time with the Pareto front and the defaults marked.
#pragma once

#include "sweep/sweep_metrics.hpp"
#include "sweep/sweep_reference.hpp"

#include <string>
#include <vector>

namespace fr {

struct SweepRow {
  std::string knob, value;  // knob "default": the current defaults
  double frame_ms = 0;      // warm median over the timed frames (kernel build excluded)
  ErrorMetrics error;
  bool on_front = false;  // on the Pareto front of (frame_ms, mean_abs_error)
};

struct SweepResult {
  std::string scene_id, device;
  int width_px = 0, height_px = 0;
  int timed_frames = 0;
  SweepReference reference;
  std::vector<SweepRow> rows;
  std::vector<std::string> notes;  // findings to print: lanes not error-neutral, default off front
};

// Marks rows on the Pareto front and adds notes: whether the default row is on the front or
// next to it (within 10% of the front's error at its time), and whether lane widths agree.
void analyse_sweep(SweepResult& result, double lanes_pixel_difference);

std::string format_sweep_table(const SweepResult& result);
std::string format_sweep_csv(const SweepResult& result);
std::string format_sweep_json(const SweepResult& result);
std::string format_sweep_svg(const SweepResult& result);

}  // namespace fr
