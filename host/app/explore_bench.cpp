#include "app/explore_bench.hpp"

#include "image/png_write.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fr {

namespace {

// A moving frame as rendered, and what it showed.
struct KeptFrame {
  Rgba8Image frame;  // at the frame's own size (the window stretches it)
  SceneState state;
};

void save_png(const std::string& path, const Rgba8Image& image) {
  std::string error;
  if (!write_png_atomic(path, image.width_px, image.height_px, image.rgba, &error))
    throw std::runtime_error(error);
}

DisplayedError judge_displayed(Explorer& explorer, const std::vector<KeptFrame>& kept, int w, int h,
                               const ExploreBenchOptions& options) {
  DisplayedError e;
  RenderSettings reference = explorer.render_settings();
  reference.width_px = w;
  reference.height_px = h;
  const SceneInfo& info = explorer.current().scene->info;
  double mae_sum = 0, ssim_sum = 0;
  for (const KeptFrame& k : kept) {
    const FrameView full = explorer.worker().render_frame(info, k.state, reference, 0,
                                                          Readback::Display, Readback::Display);
    const Rgba8Image truth{w, h, std::vector<uint8_t>(full.rgba8, full.rgba8 + size_t(w) * h * 4)};
    const Rgba8Image shown =
        upscale_bilinear(k.frame.rgba.data(), k.frame.width_px, k.frame.height_px, w, h);
    if (e.frames == options.save_frame) {
      save_png(options.save_prefix + "shown.png", shown);
      save_png(options.save_prefix + "reference.png", truth);
    }
    const double mae = mean_absolute_error(shown, truth);
    const double ssim = structural_similarity(shown, truth);
    mae_sum += mae;
    ssim_sum += ssim;
    e.max_mae = std::max(e.max_mae, mae);
    e.min_ssim = std::min(e.min_ssim, ssim);
    ++e.frames;
  }
  if (e.frames > 0) {
    e.mean_mae = mae_sum / e.frames;
    e.mean_ssim = ssim_sum / e.frames;
  }
  return e;
}

}  // namespace

ExploreBenchResult run_explore_bench(Explorer& explorer, int w, int h,
                                     const ExploreBenchOptions& options) {
  const int moving_frames = options.moving_frames;
  std::vector<KeptFrame> kept;
  using clock = std::chrono::steady_clock;
  const auto origin = clock::now();
  auto now_s = [&] { return std::chrono::duration<double>(clock::now() - origin).count(); };
  ExploreBenchResult result;
  explorer.set_mouse_look(true);
  InputState input;
  input.held.insert(Action::MoveForward);
  std::vector<double> frame_ms, trace_ms, compose_ms;
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
    const FrameView* shown = explorer.render(w, h);
    frame_ms.push_back((now_s() - start) * 1000);
    if (options.measure_error && shown && shown->rgba8)
      kept.push_back({{shown->width_px, shown->height_px,
                       std::vector<uint8_t>(shown->rgba8, shown->rgba8 + shown->pixel_count() * 4)},
                      explorer.current().state});
    scale_sum += explorer.stats().resolution_scale;
    if (const ExplorerStats& st = explorer.stats(); st.temporal) {
      ++result.temporal_frames;
      result.mean_fresh_px += static_cast<double>(st.reuse.fresh);
      result.mean_reused_px += static_cast<double>(st.reuse.reused);
      result.mean_rejected_px += static_cast<double>(st.reuse.rejected);
      result.mean_filled_px += static_cast<double>(st.reuse.filled);
      trace_ms.push_back(st.frame_ms - st.compose_ms);
      compose_ms.push_back(st.compose_ms);
    }
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
  if (result.temporal_frames > 0) {
    const double f = result.temporal_frames;
    result.mean_fresh_px /= f;
    result.mean_reused_px /= f;
    result.mean_rejected_px /= f;
    result.mean_filled_px /= f;
    result.median_trace_ms = summarize_frames(trace_ms).p50_ms;
    result.median_compose_ms = summarize_frames(compose_ms).p50_ms;
  }

  InputState still;
  const double stopped = now_s();
  bool shown = false;
  while (true) {
    const double t = now_s();
    explorer.update(still, t - last, t);
    last = t;
    const bool rendered = explorer.render(w, h) != nullptr;
    if (!rendered && explorer.stats().refined) break;
    result.refine_frame_max_ms = std::max(result.refine_frame_max_ms, (now_s() - t) * 1000);
    // (A path-traced sample renders in bands: the first frame that shows one.)
    if (rendered && !shown) {
      shown = true;
      result.seconds_to_full_resolution = now_s() - stopped;
    }
    ++result.refine_frames;
  }
  result.seconds_to_full_quality = now_s() - stopped;
  if (options.measure_error) result.moving_error = judge_displayed(explorer, kept, w, h, options);
  return result;
}

}  // namespace fr
