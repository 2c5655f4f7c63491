#include "bench/bench_report.hpp"

#include "io/json_text.hpp"

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

std::string format_bench_text(const BenchReport& r) {
  const FrameStats& s = r.stats;
  std::ostringstream out;
  out << "scene " << r.scene_id << " " << r.scene_version << ", " << r.width_px << "x"
      << r.height_px << ", " << r.precision << ", lanes " << r.lanes << ", effects: " << r.stages
      << "\n"
      << r.runs << " run(s) x " << r.frames_per_run << " frames over "
      << fixed(r.path_duration_s, 1) << " s of scene time; " << s.frames << " frames rendered in "
      << fixed(r.wall_s, 2) << " s"
      << " (kernel build and warm-up: " << fixed(r.kernel_build_ms, 0) << " ms, not counted)\n"
      << "median " << fixed(s.p50_ms) << " ms, min " << fixed(s.min_ms) << " ms, max "
      << fixed(s.max_ms) << " ms over " << s.frames << " frames\n"
      << "frame time: average " << fixed(s.mean_ms) << " ms, p50 " << fixed(s.p50_ms) << " ms, p95 "
      << fixed(s.p95_ms) << " ms\n"
      << "fps: average " << fixed(s.mean_fps) << ", min " << fixed(s.min_fps) << ", max "
      << fixed(s.max_fps) << "\n";
  if (r.run_mean_ms.size() > 1) {
    out << "average frame time per run:";
    for (double m : r.run_mean_ms) out << " " << fixed(m) << " ms";
    out << "\n";
  }
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
  std::ostringstream out;
  out << "{\n"
      << "  \"scene\": " << json_string(r.scene_id) << ",\n"
      << "  \"scene_version\": " << json_string(r.scene_version) << ",\n"
      << "  \"resolution\": {\"width\": " << r.width_px << ", \"height\": " << r.height_px << "},\n"
      << "  \"precision\": " << json_string(r.precision) << ",\n"
      << "  \"lanes\": " << r.lanes << ",\n"
      << "  \"effects\": " << json_string(r.stages) << ",\n"
      << "  \"runs\": " << r.runs << ",\n"
      << "  \"frames_per_run\": " << r.frames_per_run << ",\n"
      << "  \"path_duration_s\": " << r.path_duration_s << ",\n"
      << "  \"frames_rendered\": " << s.frames << ",\n"
      << "  \"wall_s\": " << r.wall_s << ",\n"
      << "  \"frame_ms\": {\"min\": " << s.min_ms << ", \"max\": " << s.max_ms
      << ", \"average\": " << s.mean_ms << ", \"p50\": " << s.p50_ms << ", \"p95\": " << s.p95_ms
      << "},\n"
      << "  \"fps\": {\"average\": " << s.mean_fps << ", \"min\": " << s.min_fps
      << ", \"max\": " << s.max_fps << "},\n"
      << "  \"run_average_ms\": [";
  for (size_t i = 0; i < r.run_mean_ms.size(); ++i) out << (i ? ", " : "") << r.run_mean_ms[i];
  out << "],\n"
      << "  \"system\": {\n"
      << "    \"cpu\": " << json_string(y.cpu_model) << ",\n"
      << "    \"logical_cores\": " << y.logical_cores << ",\n"
      << "    \"memory_bytes\": " << y.memory_bytes << ",\n"
      << "    \"os\": " << json_string(y.os) << ",\n"
      << "    \"opencl_platform\": " << json_string(y.opencl_platform) << ",\n"
      << "    \"opencl_device\": " << json_string(y.opencl_device) << ",\n"
      << "    \"opencl_device_version\": " << json_string(y.opencl_device_version) << ",\n"
      << "    \"opencl_driver\": " << json_string(y.opencl_driver) << "\n"
      << "  }\n"
      << "}\n";
  return out.str();
}

}  // namespace fr
