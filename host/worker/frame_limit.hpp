// frame_limit.hpp — how long the render worker may take for one sample of a scene before
// fractalis ends it as hung.
//
// Nothing can cancel a kernel whose DE never returns, so the only remedy is ending the worker,
// and the question is when. A fixed limit is either too short for a large image or far too long
// for the explorer's 30 ms frames. So in the explorer the limit follows what the scene has needed
// so far: `factor` times the slowest time per pixel it has taken in this session, times the
// pixels asked for, and never below `floor_s`; before its first sample, `first_s`. Commands that
// render (their frames may differ in cost by orders of magnitude along a camera path) use a fixed
// limit, render.watchdog_s, as before.
#pragma once

#include <cstdint>
#include <map>

namespace fr {

struct FrameLimitRule {
  bool adaptive = false;  // false: every sample gets `first_s`
  double first_s = 600;   // <= 0: no limit
  double floor_s = 5;
  double factor = 20;
};

class FrameLimit {
 public:
  explicit FrameLimit(FrameLimitRule rule = {}) : rule_(rule) {}
  // Seconds a sample of `pixels` pixels of the scene `scene_key` may take; <= 0: no limit.
  double limit_s(uint64_t scene_key, double pixels) const;
  // A sample of the scene took `seconds`.
  void record(uint64_t scene_key, double pixels, double seconds);
  // Whether a sample of the scene has been recorded.
  bool knows(uint64_t scene_key) const { return slowest_s_per_pixel_.count(scene_key) != 0; }

 private:
  FrameLimitRule rule_;
  std::map<uint64_t, double> slowest_s_per_pixel_;
};

}  // namespace fr
