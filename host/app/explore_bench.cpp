#include "app/explore_bench.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

namespace fr {

ExploreBenchResult run_explore_bench(Explorer& explorer, int w, int h, int moving_frames) {
  using clock = std::chrono::steady_clock;
  const auto origin = clock::now();
  auto now_s = [&] { return std::chrono::duration<double>(clock::now() - origin).count(); };
  ExploreBenchResult result;
  explorer.set_mouse_look(true);
  InputState input;
  input.held.insert(Action::MoveForward);
  std::vector<double> frame_ms;
  double scale_sum = 0;
  uint64_t moving_pixels = 0;
  double last = now_s();
  for (int i = 0; i < moving_frames; ++i) {
    // Weaving left and right while flying forward keeps the scene in view.
    input.look_dx = 6 * std::sin(2 * std::numbers::pi * i / 60.0);
    // A fixed 1/30 s of motion per frame: the same path on every machine and every run.
    const double start = now_s();
    explorer.update(input, 1.0 / 30.0, i / 30.0);
    last = start;
    explorer.render(w, h);
    frame_ms.push_back((now_s() - start) * 1000);
    scale_sum += explorer.stats().resolution_scale;
    if (explorer.count_evaluations()) {
      // Frames of different sizes: the sums over all their pixels, one sample each.
      const EvalCounts& c = explorer.stats().eval_counts;
      add_eval_counts(result.moving_counts, c);
      moving_pixels += c.pixels;
    }
    input.end_frame();
  }
  result.moving_counts.pixels = moving_pixels;
  result.moving_counts.samples = 1;
  result.moving = summarize_frames(frame_ms);
  result.mean_resolution_scale = scale_sum / moving_frames;

  InputState still;
  const double stopped = now_s();
  while (true) {
    const double t = now_s();
    explorer.update(still, t - last, t);
    last = t;
    const bool rendered = explorer.render(w, h) != nullptr;
    if (!rendered && explorer.stats().refined) break;
    if (result.refine_frames == 0) result.seconds_to_full_resolution = now_s() - stopped;
    ++result.refine_frames;
  }
  result.seconds_to_full_quality = now_s() - stopped;
  return result;
}

}  // namespace fr
