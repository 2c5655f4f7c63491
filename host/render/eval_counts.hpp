// eval_counts.hpp — where a frame's DE evaluations went, by stage, and how busy the packets'
// lanes were (kernels/eval_counts.cl fills the device side when the kernel is built to count).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

extern "C" {
#include "frame_constants.h"
}

namespace fr {

// A frame's counters, summed over the device's slots and over the samples rendered.
struct EvalCounts {
  std::array<uint64_t, FR_COUNT_CELLS> active{};  // evaluations lanes asked for
  std::array<uint64_t, FR_COUNT_CELLS> issued{};  // lane evaluations made (lanes x packets)
  int lanes = 1;
  uint64_t pixels = 0;  // of the frame
  int samples = 0;      // samples counted (their evaluations are all in the sums)
};

// Adds up the device buffer (uint[FR_COUNT_SLOTS][FR_COUNT_CELLS][2]).
EvalCounts sum_eval_counts(const std::vector<uint32_t>& slots, int lanes, uint64_t pixels,
                           int samples);

// Adds b's sums to a's (frames of one size and lane width): a bench's frames together.
void add_eval_counts(EvalCounts& a, const EvalCounts& b);

// One stage of one bounce: "march", "normals", "surface", "ao", "shadow light 1".
struct StageCount {
  int bounce = 0;  // 0: primary rays; 1, 2, ...: mirror bounces
  std::string stage;
  double evals_per_pixel = 0;  // per pixel per sample, by the lanes that wanted them
  // Lane evaluations made per pixel per sample (lanes x packet evaluations): what the SIMD unit
  // did, wanted or not. A packet marches at its slowest lane's pace, so this, not the
  // evaluations wanted, is what frame time follows (docs/performance.md).
  double made_per_pixel = 0;
  double utilisation = 0;  // evaluations wanted / lane evaluations made, in [0, 1]
};

// The stages that evaluated the DE at all, bounce by bounce, in pipeline order.
std::vector<StageCount> stage_counts(const EvalCounts& counts);

// All evaluations per pixel per sample, and the utilisation over all of them.
double total_evals_per_pixel(const EvalCounts& counts);
double total_made_per_pixel(const EvalCounts& counts);  // lane evaluations made
double total_utilisation(const EvalCounts& counts);

// A table for people: one line per stage, bounce sums, the total.
std::string format_eval_counts(const EvalCounts& counts);

}  // namespace fr
