#include "worker/frame_limit.hpp"

#include <algorithm>

namespace fr {

double FrameLimit::limit_s(uint64_t scene_key, double pixels) const {
  if (rule_.first_s <= 0) return 0;
  const auto it = slowest_s_per_pixel_.find(scene_key);
  if (!rule_.adaptive || it == slowest_s_per_pixel_.end()) return rule_.first_s;
  return std::max(rule_.floor_s, rule_.factor * it->second * std::max(1.0, pixels));
}

void FrameLimit::record(uint64_t scene_key, double pixels, double seconds) {
  double& slowest = slowest_s_per_pixel_[scene_key];
  slowest = std::max(slowest, seconds / std::max(1.0, pixels));
}

}  // namespace fr
