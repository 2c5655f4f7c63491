// explorer.hpp — the interactive explorer without its window: scenes, camera, frame-rate control
// and progressive refinement. The window layer (ui/) feeds it input and shows its images; tests
// and `bench --explore` drive it headless.
#pragma once

#include "app/camera_controller.hpp"
#include "app/frame_controller.hpp"
#include "app/input.hpp"
#include "app/path_recorder.hpp"
#include "app/sample_bands.hpp"
#include "app/kernel_warmup.hpp"
#include "app/scene_library.hpp"
#include "app/temporal_reuse.hpp"
#include "render/renderer.hpp"
#include "settings/settings.hpp"
#include "worker/render_worker.hpp"

#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fr {

struct ExplorerStats {
  double frame_ms = 0;  // last render (update excluded)
  double resolution_scale = 1;
  // How the last moving frame was made: temporal reuse (a lattice of 1 in stride_x * stride_y
  // pixels traced, the rest carried from earlier frames, `reuse` says how many of each) or a
  // scaled frame (more than the camera changed, or explorer.temporal is off).
  bool temporal = false;
  int stride_x = 1, stride_y = 1;
  ReuseCounts reuse;
  double compose_ms = 0;  // of frame_ms, carrying the earlier frames' pixels (temporal)
  int sample_index = 0;
  bool refined = false;  // full quality reached and shown
  // A parked view being path-traced (render.integrator = "path"): its samples so far (0: not
  // path-traced), and the noise left, as the mean's standard error relative to its brightness
  // (app/noise_estimate.hpp; from the second sample on, and only unfiltered: the estimate reads
  // the steps of the plain running mean, which the denoiser's output does not take).
  int path_samples = 0;
  std::optional<double> path_noise;
  bool path_denoised = false;  // the shown picture is filtered (explorer.denoise)
  double de_steps_per_pixel = 0;
  double out_of_steps_fraction = 0;  // primary rays of the last full frame that ran out of steps
  Precision precision = Precision::Float;  // what the last frame ran in (auto resolved)
  double surface_distance = 0;             // DE at the eye
  // The depth: a pixel's footprint at the nearest surface (the DE at the eye times the pixel
  // angle), "pixel 3.2e-21" in the overlay; and whether the view is past what the last frame's
  // number type resolves there while the scene has no pair estimate, or one that is only double
  // at these parameters (pairs_unresolved; said, never drawn silently).
  double pixel_footprint = 0;
  bool past_resolution = false;
  bool pairs_unresolved = false;
  // What render.auto_iterations raised for the last frame ("iterations 72 (set 14)"; "": nothing).
  std::string raised_iterations;
  // Where the last full frame's DE evaluations went, while counting is on (samples 0: off).
  EvalCounts eval_counts;
};

// Where a screenshot's view goes: the image's name with .toml for its extension.
std::filesystem::path screenshot_view_file(const std::filesystem::path& image);

class Explorer {
 public:
  // Renders in `worker` (every scene kernel runs there: worker/render_worker.hpp).
  Explorer(const Settings& settings, RenderWorker& worker, SceneLibrary& library,
           const std::string& scene_id);

  // One frame's update: triggered actions, camera, the scene's update callback at scene time
  // `now_s`, and the plugin folders. Returns false when the user asked to quit.
  bool update(const InputState& input, double dt_s, double now_s);

  // Renders what the frame controller plans for a window of this size. Returns null when the
  // image is already at full quality (nothing new to show). The frame is read where the render
  // worker left it: valid until the next update() or render().
  const FrameView* render(int window_width_px, int window_height_px);

  // Focuses the thin lens on the surface under image pixel (x, y) of a width x height window:
  // render.focus_distance becomes that surface's distance along the view (the march finds it:
  // the pinhole ray through the pixel's centre, traced alone with every step). Returns it, or
  // nothing where the ray meets no surface (the focus stays). A click on the picture does this
  // at the next render(). Throws what the render worker throws.
  std::optional<double> focus_at(int x, int y, int width_px, int height_px);
  // The distance from the eye to the surface under image pixel (x, y) of a width x height window
  // along the pixel's ray (traced alone, finer than a frame's rays), or nothing where it meets
  // none. Throws what the render worker throws.
  std::optional<double> depth_under(int x, int y, int width_px, int height_px);

  // Writes a PNG (or, for a file named *.exr, an OpenEXR file with its passes) of the current
  // view at the given size with full-quality samples, in bands (image/poster.hpp), and the view
  // beside it as a preset (screenshot_view_file: parameters, and eye and target with every digit
  // a deep view has), which `--preset FILE` opens again.
  bool screenshot(const std::filesystem::path& file, int width_px, int height_px,
                  std::string* error);

  void select_scene(int index);
  int current_index() const { return current_; }
  SceneSlot& current() { return library_.slots()[current_]; }
  SceneLibrary& library() { return library_; }
  RenderWorker& worker() { return worker_; }
  RenderSettings& render_settings() { return settings_.render; }
  Settings& settings() { return settings_; }
  CameraMode camera_mode() const { return mode_; }
  void set_camera_mode(CameraMode m) { mode_ = m; }
  bool mouse_look() const { return mouse_look_; }
  // Temporal reuse traces this lattice while moving, whatever the frame time (bench --lattice).
  void fix_lattice(int stride_x, int stride_y) { frames_.fix_lattice(stride_x, stride_y); }
  void set_mouse_look(bool on) { mouse_look_ = on; }
  // Per-stage DE counters (render/eval_counts.hpp): a counting kernel, a little slower.
  bool count_evaluations() const { return count_evaluations_; }
  void set_count_evaluations(bool on);
  // Something outside update() (the overlay) changed the scene or settings: refine again (and
  // reuse nothing of the frames before).
  void mark_changed() {
    changed_ = true;
    scene_changed_ = true;
  }
  // The current scene's code changed under it (edit mode swapped its DE): whatever took the
  // render worker down before is tried again, and the view refines again. `quick_first_frame`:
  // that frame is built without LLVM's optimizations (RenderSettings::quick_build), in the
  // precision the last frame used and without the cone pre-pass (both only ever make a frame
  // faster, at the cost of another kernel build), so that it is on screen sooner; the frames
  // after it are the optimized build's.
  // After the quick frame, frames stay quick builds while the optimized kernels (and the probe's)
  // are built in the background (app/kernel_warmup.hpp): the window answers meanwhile.
  void scene_code_changed(bool quick_first_frame = false) {
    failed_state_.reset();
    changed_ = true;
    scene_changed_ = true;
    quick_frame_ = quick_first_frame;
    warming_ = false;  // a warm-up under way is for the code before
    warmup_wanted_.reset();
  }
  // Frames rendered, and render-worker failures (a crash, a hang, a limit), since the start.
  uint64_t frames_rendered() const { return frames_rendered_; }
  // Of those, the frames of optimized builds (not edit mode's quick ones).
  uint64_t optimized_frames_rendered() const { return frames_rendered_ - quick_frames_rendered_; }
  int worker_failures() const { return worker_failures_; }

  // The camera path being recorded or played (app/path_recorder.hpp). While it plays, the
  // camera and parameters follow it and flying is paused.
  PathRecorder& path() { return path_; }

  const ExplorerStats& stats() const { return stats_; }
  const std::vector<Action>& pending_window_actions() const { return window_actions_; }

 private:
  // The render worker ended (a DE crashed or hung it): say so, and go back to the last state that
  // rendered, so that the next frame (in a fresh worker) shows a picture again.
  void worker_failed(SceneSlot& slot, const RenderWorkerFailure& failure);
  // The slot's scene and state are what took the worker down last: not tried again (a fresh
  // worker and the same error every frame) until one of them changes.
  bool took_the_worker_down(const SceneSlot& slot) const;
  // Times the bands of a path-traced sample and its filter (app/sample_bands.hpp) after a call
  // that queued `rows` rows of `bands` (read_back: and read the frame back; rows 0 and no bands
  // for a read-back alone); `call_ms`, the call's own time.
  void time_band(SampleBands* bands, int rows, bool read_back, double call_ms);

  RenderWorker& worker_;
  SceneLibrary& library_;
  // The last scene and state that rendered; and the state that took the worker down, not tried
  // again until something changes.
  std::string good_scene_id_;
  std::optional<SceneState> good_state_;
  std::string failed_scene_id_;
  std::optional<SceneState> failed_state_;
  Settings settings_;
  CameraControls controls_;
  FrameController frames_;
  CameraMode mode_ = CameraMode::Fly;
  bool mouse_look_ = false;
  int current_ = 0;
  bool changed_ = true;
  // More than the camera changed since the last frame: earlier frames' pixels are not reused.
  bool scene_changed_ = true;
  // The last render() found the current scene not usable yet (preparing or refused).
  bool waiting_for_scene_ = false;
  TemporalReuse reuse_;
  // The path-traced sample under way in bands, and its filter's passes (filter_pass_: the pass
  // to queue next, kDenoisePasses once all are, -1 while the sample is not whole); the rows of
  // the band queued last, not yet timed (0: none), whose bands they were, and when the call that
  // queued it returned.
  SampleBands bands_{1000.0 / 30.0};
  SampleBands filter_bands_{1000.0 / 30.0};
  int filter_pass_ = -1;
  int queued_band_rows_ = 0;
  SampleBands* queued_band_of_ = nullptr;
  std::chrono::steady_clock::time_point queued_band_at_;
  std::vector<float> previous_linear_;  // the path-traced view's mean before its latest sample
  std::optional<std::pair<int, int>> pending_focus_;  // a click, focused at the next render
  int window_width_px_ = 0, window_height_px_ = 0;    // of the last render(): the zoom's pixels
  uint64_t lattice_frames_ = 0;                       // the lattice phase's clock
  bool quick_frame_ = false;  // the next frame is a quick build (scene_code_changed)
  // The quick frames wait for a warm-up of the optimized kernels: wanted (to start when the
  // warm-up's thread is free) or under way.
  bool warming_ = false;
  std::optional<WarmupJob> warmup_wanted_;
  std::unique_ptr<KernelWarmup> warmup_;  // made by the first warm-up
  uint64_t quick_frames_rendered_ = 0;
  bool count_evaluations_ = false;
  uint64_t frames_rendered_ = 0;
  int worker_failures_ = 0;
  ExplorerStats stats_;
  PathRecorder path_;
  FrameView last_;                      // the last frame rendered (see render)
  std::vector<Action> window_actions_;  // overlay, fullscreen, screenshot: for the window layer
};

}  // namespace fr
