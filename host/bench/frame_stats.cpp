#include "bench/frame_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace fr {
double percentile(std::vector<double> values, double percent) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(percent / 100.0 * double(values.size()));
  return values[static_cast<size_t>(std::clamp(rank, 1.0, double(values.size()))) - 1];
}

FrameStats summarize_frames(std::vector<double> frame_ms) {
  if (frame_ms.empty()) throw std::invalid_argument("summarize_frames: no frames");
  std::sort(frame_ms.begin(), frame_ms.end());
  FrameStats s;
  s.frames = frame_ms.size();
  s.total_ms = std::accumulate(frame_ms.begin(), frame_ms.end(), 0.0);
  s.min_ms = frame_ms.front();
  s.max_ms = frame_ms.back();
  s.mean_ms = s.total_ms / static_cast<double>(s.frames);
  s.p50_ms = percentile(frame_ms, 50);
  s.p95_ms = percentile(frame_ms, 95);
  s.mean_fps = 1000.0 / s.mean_ms;
  s.min_fps = 1000.0 / s.max_ms;
  s.max_fps = 1000.0 / s.min_ms;
  return s;
}

std::vector<double> time_frames(int count, const std::function<void(int)>& render_frame,
                                const std::function<double()>& now_ms) {
  std::vector<double> out;
  out.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double start = now_ms();
    render_frame(i);
    out.push_back(now_ms() - start);
  }
  return out;
}

}  // namespace fr
