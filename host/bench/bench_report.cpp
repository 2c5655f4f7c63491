#include "bench/bench_report.hpp"

#include "io/json_text.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace fr {
namespace {

std::string fixed(double v, int digits = 2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

}  // namespace

// Pixel samples a second at the median frame time: what an integrator delivers.
double samples_per_second(const BenchReport& r) {
  if (r.stats.p50_ms <= 0) return 0;
  return static_cast<double>(r.width_px) * r.height_px * r.samples_per_frame /
         (r.stats.p50_ms / 1000.0);
}

std::string format_bench_text(const BenchReport& r) {
  const FrameStats& s = r.stats;
  std::ostringstream out;
  out << "scene " << r.scene_id << " " << r.scene_version << ", " << r.width_px << "x"
      << r.height_px << ", " << r.precision << ", lanes " << r.lanes << ", effects: " << r.stages
      << "\n"
      << r.runs << " run(s) x " << r.frames_per_run << " frames over "
      << fixed(r.path_duration_s, 1) << " s of scene time"
      << (r.camera_path.empty() ? "" : " along " + r.camera_path) << "; " << s.frames
      << " frames rendered in " << fixed(r.wall_s, 2) << " s"
      << " (kernel build and warm-up: " << fixed(r.kernel_build_ms, 0) << " ms, not counted)\n"
      << "median " << fixed(s.p50_ms) << " ms, min " << fixed(s.min_ms) << " ms, max "
      << fixed(s.max_ms) << " ms over " << s.frames << " frames\n"
      << "frame time: average " << fixed(s.mean_ms) << " ms, p50 " << fixed(s.p50_ms) << " ms, p95 "
      << fixed(s.p95_ms) << " ms\n"
      << "fps: average " << fixed(s.mean_fps) << ", min " << fixed(s.min_fps) << ", max "
      << fixed(s.max_fps) << "\n";
  if (s.p50_ms > 0)
    out << "integrator " << r.integrator << ", " << r.samples_per_frame
        << " sample(s) a pixel a frame: " << fixed(samples_per_second(r) / 1e6, 3)
        << " M samples per second (median frame)\n";
  if (r.run_mean_ms.size() > 1) {
    out << "average frame time per run:";
    for (double m : r.run_mean_ms) out << " " << fixed(m) << " ms";
    out << "\n";
  }
  if (r.counts.samples > 0) out << format_eval_counts(r.counts);
  const SystemInfo& y = r.system;
  out << "system: " << y.cpu_model << ", " << y.logical_cores << " logical cores, "
      << fixed(static_cast<double>(y.memory_bytes) / (1024.0 * 1024 * 1024), 1) << " GiB, " << y.os
      << "\n"
      << "OpenCL: " << y.opencl_device << " (" << y.opencl_platform << "), "
      << y.opencl_device_version << ", driver " << y.opencl_driver << "\n";
  return out.str();
}

std::string format_bench_json(const BenchReport& r) {
  const FrameStats& s = r.stats;
  const SystemInfo& y = r.system;
  nlohmann::ordered_json stages = nlohmann::ordered_json::array();
  for (const StageCount& c : stage_counts(r.counts))
    stages.push_back({{"bounce", c.bounce},
                      {"stage", c.stage},
                      {"per_pixel", c.evals_per_pixel},
                      {"made_per_pixel", c.made_per_pixel},
                      {"utilisation", c.utilisation}});
  nlohmann::ordered_json j = {
      {"scene", r.scene_id},
      {"scene_version", r.scene_version},
      {"resolution", {{"width", r.width_px}, {"height", r.height_px}}},
      {"precision", r.precision},
      {"lanes", r.lanes},
      {"effects", r.stages},
      {"integrator", r.integrator},
      {"samples_per_frame", r.samples_per_frame},
      {"samples_per_second", samples_per_second(r)},
      {"runs", r.runs},
      {"frames_per_run", r.frames_per_run},
      {"path_duration_s", r.path_duration_s},
      {"camera_path", r.camera_path},
      {"frames_rendered", s.frames},
      {"wall_s", r.wall_s},
      {"frame_ms",
       {{"min", s.min_ms},
        {"max", s.max_ms},
        {"average", s.mean_ms},
        {"p50", s.p50_ms},
        {"p95", s.p95_ms}}},
      {"fps", {{"average", s.mean_fps}, {"min", s.min_fps}, {"max", s.max_fps}}},
      {"run_average_ms", r.run_mean_ms},
      {"system",
       {{"cpu", y.cpu_model},
        {"logical_cores", y.logical_cores},
        {"memory_bytes", y.memory_bytes},
        {"os", y.os},
        {"opencl_platform", y.opencl_platform},
        {"opencl_device", y.opencl_device},
        {"opencl_device_version", y.opencl_device_version},
        {"opencl_driver", y.opencl_driver}}},
  };
  if (r.counts.samples > 0)
    j["de_evaluations"] = {{"per_pixel", total_evals_per_pixel(r.counts)},
                           {"made_per_pixel", total_made_per_pixel(r.counts)},
                           {"utilisation", total_utilisation(r.counts)},
                           {"lanes", r.counts.lanes},
                           {"stages", stages}};
  return json_text(j);
}

}  // namespace fr
