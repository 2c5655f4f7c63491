#include "render/eval_counts.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace fr {
namespace {

std::string kind_name(int kind) {
  switch (kind) {
    case FR_COUNT_MARCH:
      return "march";
    case FR_COUNT_NORMALS:
      return "normals";
    case FR_COUNT_SURFACE:
      return "surface colour";
    case FR_COUNT_AO:
      return "ao";
    case FR_COUNT_CONE:
      return "cone pre-pass";
    default:
      return "shadow light " + std::to_string(kind - FR_COUNT_SHADOW + 1);
  }
}

double per_pixel(const EvalCounts& c, uint64_t evals) {
  const double samples_px = static_cast<double>(c.pixels) * std::max(1, c.samples);
  return samples_px > 0 ? static_cast<double>(evals) / samples_px : 0.0;
}

double utilisation(uint64_t active, uint64_t issued) {
  return issued > 0 ? static_cast<double>(active) / static_cast<double>(issued) : 0.0;
}

std::string bounce_name(int bounce) {
  return bounce == 0 ? "primary" : "bounce " + std::to_string(bounce);
}

}  // namespace

EvalCounts sum_eval_counts(const std::vector<uint32_t>& slots, int lanes, uint64_t pixels,
                           int samples) {
  EvalCounts c;
  c.lanes = lanes;
  c.pixels = pixels;
  c.samples = samples;
  for (size_t slot = 0; slot < slots.size() / (2 * FR_COUNT_CELLS); ++slot)
    for (int cell = 0; cell < FR_COUNT_CELLS; ++cell) {
      c.active[cell] += slots[(slot * FR_COUNT_CELLS + cell) * 2 + 0];
      c.issued[cell] += slots[(slot * FR_COUNT_CELLS + cell) * 2 + 1];
    }
  return c;
}

void add_eval_counts(EvalCounts& a, const EvalCounts& b) {
  for (int cell = 0; cell < FR_COUNT_CELLS; ++cell) {
    a.active[cell] += b.active[cell];
    a.issued[cell] += b.issued[cell];
  }
  a.lanes = b.lanes;
  a.pixels = b.pixels;
  a.samples += b.samples;
}

std::vector<StageCount> stage_counts(const EvalCounts& c) {
  std::vector<StageCount> rows;
  for (int bounce = 0; bounce <= FR_COUNT_MAX_BOUNCES; ++bounce)
    for (int kind = 0; kind < FR_COUNT_KINDS; ++kind) {
      const int cell = bounce * FR_COUNT_KINDS + kind;
      if (c.issued[cell] == 0) continue;
      rows.push_back({bounce, kind_name(kind), per_pixel(c, c.active[cell]),
                      per_pixel(c, c.issued[cell]),
                      utilisation(c.active[cell], c.issued[cell])});
    }
  return rows;
}

double total_evals_per_pixel(const EvalCounts& c) {
  uint64_t active = 0;
  for (uint64_t a : c.active) active += a;
  return per_pixel(c, active);
}

double total_made_per_pixel(const EvalCounts& c) {
  uint64_t issued = 0;
  for (uint64_t i : c.issued) issued += i;
  return per_pixel(c, issued);
}

double total_utilisation(const EvalCounts& c) {
  uint64_t active = 0, issued = 0;
  for (int cell = 0; cell < FR_COUNT_CELLS; ++cell) {
    active += c.active[cell];
    issued += c.issued[cell];
  }
  return utilisation(active, issued);
}

std::string format_eval_counts(const EvalCounts& c) {
  std::ostringstream out;
  char line[160];
  std::snprintf(line, sizeof line,
                "DE evaluations per pixel (lanes %d; utilisation: busy lanes; made: lane "
                "evaluations, busy or not)\n",
                c.lanes);
  out << line;
  const std::vector<StageCount> rows = stage_counts(c);
  for (size_t i = 0; i < rows.size(); ++i) {
    const StageCount& r = rows[i];
    std::snprintf(line, sizeof line, "  %-8s %-15s %9.2f  %5.1f%%  made %7.2f\n",
                  bounce_name(r.bounce).c_str(), r.stage.c_str(), r.evals_per_pixel,
                  100.0 * r.utilisation, r.made_per_pixel);
    out << line;
  }
  std::snprintf(line, sizeof line, "  %-24s %9.2f  %5.1f%%  made %7.2f\n", "total",
                total_evals_per_pixel(c), 100.0 * total_utilisation(c), total_made_per_pixel(c));
  out << line;
  return out.str();
}

}  // namespace fr
