#include "app/explorer.hpp"
#include "app/noise_estimate.hpp"

#include "image/exr_write.hpp"
#include "image/poster.hpp"
#include "io/atomic_file.hpp"
#include "path/preset.hpp"
#include "render/camera.hpp"
#include "render/device.hpp"
#include "render/eye_relative.hpp"
#include "render/kernel_assembly.hpp"
#include "render/memory_budget.hpp"
#include "render/precision.hpp"
#include "scene/vec3.hpp"

#include <spdlog/spdlog.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace fr {
namespace {

// Everything of the state that the image depends on, but the camera.
bool same_scene(const SceneState& a, const SceneState& b) {
  // (No memcmp of empty vectors: their data() may be null.)
  return a.params.size() == b.params.size() &&
         (a.params.empty() ||
          std::memcmp(a.params.data(), b.params.data(), a.params.size() * sizeof(fr_value)) == 0) &&
         a.lights.size() == b.lights.size() &&
         (a.lights.empty() ||
          std::memcmp(a.lights.data(), b.lights.data(), a.lights.size() * sizeof(fr_light)) == 0) &&
         a.bounding_radius == b.bounding_radius;
}

bool same_state(const SceneState& a, const SceneState& b) {
  return same_scene(a, b) && std::memcmp(&a.camera, &b.camera, sizeof(fr_camera)) == 0;
}

}  // namespace

Explorer::Explorer(const Settings& settings, RenderWorker& worker, SceneLibrary& library,
                   const std::string& scene_id)
    : worker_(worker), library_(library), settings_(settings) {
  controls_.mouse_sensitivity_deg_per_px = settings.explorer.mouse_sensitivity_deg_per_px;
  controls_.invert_y = settings.explorer.invert_y;
  controls_.speed_per_distance = settings.explorer.speed;
  FrameControllerSettings frame;
  frame.target_frame_ms = 1000.0 / settings.explorer.target_fps;
  frame.full_quality_samples = settings.explorer.full_quality_samples;
  frames_ = FrameController(frame);
  bands_ = SampleBands(frame.target_frame_ms);
  filter_bands_ = SampleBands(frame.target_frame_ms);
  if (library_.slots().empty()) throw std::runtime_error("no scene could be loaded");
  const int index = library_.find(scene_id);
  current_ = index >= 0 ? index : 0;
  if (index < 0) spdlog::warn("no scene '{}'; showing '{}'", scene_id, current().scene->info.id);
  library_.prioritize(current_);
}

void Explorer::select_scene(int index) {
  const int count = static_cast<int>(library_.slots().size());
  if (count == 0) return;
  index = ((index % count) + count) % count;
  if (index == current_) return;
  const int previous = current_;
  current_ = index;
  // A removed scene goes once the user has switched away from it.
  if (library_.slots()[previous].removed) {
    library_.drop_if_removed(previous);
    if (previous < current_) --current_;
  }
  changed_ = true;
  scene_changed_ = true;
  // Edit mode's quick frames and their warm-up were the scene before's.
  quick_frame_ = warming_ = false;
  warmup_wanted_.reset();
  library_.prioritize(current_);
}

bool Explorer::update(const InputState& input, double dt_s, double now_s) {
  window_actions_.clear();
  for (Action a : input.triggered) {
    switch (a) {
      case Action::Quit:
        return false;
      case Action::NextScene:
        select_scene(current_ + 1);
        break;
      case Action::PreviousScene:
        select_scene(current_ - 1);
        break;
      case Action::ToggleCameraMode:
        mode_ = mode_ == CameraMode::Fly ? CameraMode::Orbit : CameraMode::Fly;
        break;
      case Action::ToggleMouseLook:
        mouse_look_ = !mouse_look_;
        break;
      case Action::AddKeyframe:
        add_keyframe(path_, current().scene->info, current().state);
        spdlog::info("keyframe {} at {:g} s", path_.keyframes.size(),
                     path_.keyframes.back().time_s);
        break;
      case Action::PlayPath:
        toggle_playback(path_, current().scene->info);
        break;
      default:
        window_actions_.push_back(a);
        break;
    }
  }
  if (input.resized) changed_ = scene_changed_ = true;
  if (input.clicked) pending_focus_ = input.clicked;
  for (const SceneEvent& e : library_.poll(now_s, settings_.render)) {
    if (e.kind == SceneEvent::Kind::Reloaded && e.scene_id == current().scene->info.id)
      changed_ = scene_changed_ = true;
    log_scene_event(e);
  }

  SceneSlot& slot = current();
  // The flying speed follows the scene's own DE at the eye, evaluated on the device. Not while a
  // changed DE waits for its quick frame: the probe would be a kernel build before it (the last
  // distance serves for a frame), and one that hangs is better found by that frame, which edit
  // mode then undoes before anything probes it again.
  // Past float, a scene with a pair estimate is probed in pairs at the eye itself (the float
  // eye of the plain probe is 1e-7 of the scene off it: a deep view's whole world).
  const bool pairs = has_pair_estimate(slot.scene->info) && stats_.precision != Precision::Float;
  const std::array<float, 3> eye_f = to_float3(slot.state.camera.eye);
  const bool probe_ok = !took_the_worker_down(slot) && slot.usable();
  ZoomPoint zoom_point;
  bool zoom_to_point = false;
  try {
    if (!probe_ok) {
      stats_.surface_distance = 0.1;  // (an unvetted DE is never run: it might not return)
    } else if (!quick_frame_ && pairs) {
      PairOrigin origin;
      const auto eye = eye_pairs(slot.state.camera, slot.state.camera_lo);
      std::copy(eye.begin(), eye.end(), origin.eye);
      stats_.surface_distance = worker_.probe_de(slot.scene->info, slot.state.params, {{0, 0, 0}},
                                                 1, Precision::DoubleDouble, &origin)[0];
    } else if (!quick_frame_) {
      stats_.surface_distance = worker_.probe_de(slot.scene->info, slot.state.params, {eye_f})[0];
    }
    // A zoom in fly mode goes towards the surface under the pointer (camera_controller.hpp).
    if (probe_ok && !path_.playing && mode_ == CameraMode::Fly && zoom_notches(input, dt_s) != 0 &&
        window_width_px_ > 0 && window_height_px_ > 0) {
      const auto [x, y] = mouse_look_ || !input.pointer
                              ? std::pair(window_width_px_ / 2, window_height_px_ / 2)
                              : *input.pointer;
      if (const auto d = depth_under(x, y, window_width_px_, window_height_px_)) {
        const CameraRays rays =
            view_camera_rays(slot.state, window_width_px_, window_height_px_,
                             settings_.render.mirror_vertical, settings_.render.pixel_corners);
        const glm::dvec3 dir = camera_ray_dir(rays, x, y);
        store_dvec3(zoom_point.dir, dir);
        zoom_point.distance = *d;
        zoom_to_point = true;
      }
    }
  } catch (const RenderWorkerFailure& e) {
    worker_failed(slot, e);
    stats_.surface_distance = 0.1;
  } catch (const std::exception& e) {
    slot.error = e.what();
    stats_.surface_distance = 0.1;
  }
  if (window_width_px_ > 0 && window_height_px_ > 0) {
    const CameraRays rays = view_camera_rays(slot.state, window_width_px_, window_height_px_);
    stats_.pixel_footprint = std::abs(stats_.surface_distance) * rays.pixel_angle_rad;
    // Past double there, and nothing finer to render it in: said in the overlay. A pair
    // estimate that is only double at these parameters counts as none (asked only that deep).
    const bool past_double =
        stats_.pixel_footprint < kDoubleFootprintUlps * position_epsilon(Precision::Double) *
                                     std::max(glm::length(rays.eye), slot.state.bounding_radius);
    stats_.pairs_unresolved = false;
    if (past_double && pairs && probe_ok && !quick_frame_) {
      try {
        const PairProbe probe = [&](const std::vector<std::array<float, 3>>& points,
                                    const PairOrigin& origin) {
          return worker_.probe_de(slot.scene->info, slot.state.params, points, 1,
                                  Precision::DoubleDouble, &origin);
        };
        stats_.pairs_unresolved = !pair_estimate_resolves_view(probe, slot.state, rays);
      } catch (const RenderWorkerFailure& e) {
        worker_failed(slot, e);
      } catch (const std::exception& e) {
        slot.error = e.what();
      }
    }
    stats_.past_resolution =
        past_double && (!has_pair_estimate(slot.scene->info) || stats_.pairs_unresolved);
  }
  const SceneState before = slot.state;
  if (path_.playing)
    advance_playback(path_, slot.scene->info, dt_s, slot.state);
  else if (update_camera(slot.state.camera, slot.state.camera_lo, mode_, input, mouse_look_, dt_s,
                         stats_.surface_distance, controls_, zoom_to_point ? &zoom_point : nullptr)
               .moved)
    changed_ = true;
  std::string error;
  // A failed update keeps the scene's last good state on screen (the camera still flies); it is
  // said once, not every frame, and the scene stays failed until it is reloaded.
  if (!slot.instance->update(slot.state, now_s, &error) && slot.error != error) {
    slot.error = error;
    spdlog::error("scene '{}': {}", slot.scene->info.id, error);
  }
  if (!same_state(before, slot.state)) changed_ = true;
  // An animated parameter or light: nothing of the frames before may be reused (FR-2.4).
  if (!same_scene(before, slot.state)) scene_changed_ = true;
  return true;
}

const FrameView* Explorer::render(int window_width_px, int window_height_px) {
  window_width_px_ = window_width_px;
  window_height_px_ = window_height_px;
  // A scene still waiting for its test render (or refused by it) is not rendered: its DE might
  // never return. The window shows what is being prepared (ui/overlay.hpp) meanwhile.
  if (!current().usable()) {
    waiting_for_scene_ = true;
    pending_focus_.reset();
    return nullptr;
  }
  if (waiting_for_scene_) {
    waiting_for_scene_ = false;
    changed_ = scene_changed_ = true;
  }
  // Edit mode's warm-up of the optimized kernels (kernel_warmup.hpp): started when its thread is
  // free; once done, the next frame is the optimized build's, found in the compiler's cache.
  if (warmup_wanted_ && warmup_->done()) {
    warmup_->start(std::move(*warmup_wanted_));
    warmup_wanted_.reset();
  } else if (warming_ && !warmup_wanted_ && warmup_->done()) {
    warming_ = false;
    quick_frame_ = false;
    changed_ = true;
  }
  if (pending_focus_) {
    const auto [x, y] = *pending_focus_;
    pending_focus_.reset();
    try {
      if (const auto d = focus_at(x, y, window_width_px, window_height_px))
        spdlog::info(
            "focus at {:.4g}, the surface under pixel ({}, {}){}", *d, x, y,
            settings_.render.aperture_radius > 0 ? "" : " (no depth of field: aperture 0)");
      else
        spdlog::info("no surface under pixel ({}, {}): the focus stays at {:.4g}", x, y,
                     settings_.render.focus_distance);
    } catch (const RenderWorkerFailure& e) {
      worker_failed(current(), e);
      return nullptr;
    } catch (const std::exception& e) {
      spdlog::error("focusing at pixel ({}, {}): {}", x, y, e.what());
    }
  }
  // Temporal reuse (app/temporal_reuse.hpp) while only the camera moves; a frame after anything
  // else changed is scaled, as with reuse off, and keeps nothing of the frames before it.
  // Not past double: reuse carries samples between cameras in world coordinates, in double,
  // which cannot tell a deep view's eye positions apart (pairs: docs/deep_zoom.md).
  const bool deep = stats_.precision == Precision::DoubleDouble;
  const bool temporal_next = settings_.explorer.temporal && !deep;  // (once not quick)
  const bool temporal = temporal_next && !quick_frame_;
  if (scene_changed_ || deep) reuse_.reset();
  // With the path integrator chosen, a parked view accumulates its samples; flying stays fast.
  const bool path = settings_.render.integrator == Integrator::Path;
  frames_.set_full_quality_samples(path ? settings_.explorer.path_samples
                                        : settings_.explorer.full_quality_samples);
  const FramePlan plan = frames_.plan(changed_, temporal && !scene_changed_);
  changed_ = false;
  scene_changed_ = false;
  stats_.resolution_scale = plan.resolution_scale;
  stats_.sample_index = plan.sample_index;
  stats_.refined = plan.done;
  if (plan.done) return nullptr;
  RenderSettings s = settings_.render;
  // Moving frames, and the quick frame after an edit, on the fast integrator: a path-traced
  // sample costs several of its frames, and one alone is mostly noise.
  const bool path_sample = path && plan.still && !quick_frame_;
  if (!path_sample) s.integrator = Integrator::Fast;
  // The path-traced preview filtered (explorer.denoise) for its first samples, where the filter
  // helps most: it costs about two Mandelbulb samples at 1280x720 (docs/rendering.md), so the
  // rest accumulate unfiltered, and the overlay shows their noise. The fast frames, lattices
  // among them (windows, which the filter cannot take), never.
  constexpr int kDenoisedPreviewSamples = 16;
  s.denoise =
      path_sample && settings_.explorer.denoise && plan.sample_index < kDenoisedPreviewSamples;
  const int window_w = std::max(1, window_width_px), window_h = std::max(1, window_height_px);
  LatticePhase phase;  // strides 1: the whole window (a full frame kept for reuse)
  if (plan.lattice) {
    phase = lattice_phase(plan.stride_x, plan.stride_y, lattice_frames_++);
    s.window = ImageWindow{window_w, window_h, phase.x0, phase.y0, phase.stride_x, phase.stride_y};
    s.width_px = phase.width_px(window_w);
    s.height_px = phase.height_px(window_h);
  } else {
    s.width_px = std::max(1, static_cast<int>(std::lround(window_w * plan.resolution_scale)));
    s.height_px = std::max(1, static_cast<int>(std::lround(window_h * plan.resolution_scale)));
  }
  s.max_steps = std::max(16, static_cast<int>(s.max_steps * plan.step_budget));
  s.count_evaluations = count_evaluations_;
  SceneSlot& slot = current();
  if (took_the_worker_down(slot)) return nullptr;
  const bool quick = quick_frame_;
  if (quick) {
    s.quick_build = true;
    s.cone_prepass = false;
    // A quarter of the pixels: the unoptimized kernel is four to six times slower, and this frame
    // only has to show the change until the optimized build's, a few seconds later.
    s.width_px = std::max(1, s.width_px / 2);
    s.height_px = std::max(1, s.height_px / 2);
    // Packets of 4 rays rather than a CPU's 16: half the code to compile (PoCL: 0.21 s against
    // 0.47 s at -cl-opt-disable), and as fast a frame at this size.
    if (const int lanes = s.lanes > 0 ? s.lanes : preferred_lanes(worker_.device(), s.precision);
        lanes > 4)
      s.lanes = 4;
    // Auto would probe the new DE in double first: another kernel build before the frame.
    if (s.precision == Precision::Auto && good_scene_id_ == slot.scene->info.id)
      s.precision = stats_.precision;
  }
  // The frames whose pixels are kept for reuse: the lattices, and the first full-resolution
  // sample once parked (the next flight starts from it).
  const bool keep = temporal && !quick && !path_sample && plan.sample_index == 0 &&
                    (plan.lattice || plan.resolution_scale == 1);
  // A path-traced sample in bands of rows (app/sample_bands.hpp), and with the filter on, its
  // passes in bands too: each call queues one and returns with nothing new to show (the picture
  // stays until the sample is whole and filtered); the last call reads the frame back.
  SampleBand band;
  bool filtered = false;  // this call reads back a sample that denoise_rows filtered
  if (!path_sample) {
    bands_.reset();
    filter_bands_.reset();
    filter_pass_ = -1;
    queued_band_rows_ = 0;
  } else if (filter_pass_ >= Renderer::kDenoisePasses) {
    filtered = true;
    filter_pass_ = -1;
  } else {
    const bool filtering = filter_pass_ >= 0;
    band = filtering ? filter_bands_.next(filter_pass_, s.height_px)
                     : bands_.next(plan.sample_index, s.height_px);
    if (filtering || !band.last || s.denoise) {
      const auto queued_from = std::chrono::steady_clock::now();
      try {
        if (filtering)
          worker_.denoise_rows(s, filter_pass_, band.rows);
        else
          worker_.render_sample(slot.scene->info, slot.state, s, plan.sample_index,
                                Readback::Everything, band.rows);
      } catch (const RenderWorkerFailure& e) {
        last_ = FrameView{};
        filter_pass_ = -1;
        worker_failed(slot, e);
        return nullptr;
      } catch (const std::exception& e) {
        last_ = FrameView{};
        filter_pass_ = -1;
        if (slot.error != e.what()) spdlog::error("{}", e.what());
        slot.error = e.what();
        return nullptr;
      }
      if (band.last) ++filter_pass_;  // the sample whole: the first pass; a pass whole: the next
      frames_.sample_unfinished();
      time_band(
          filtering ? &filter_bands_ : &bands_, band.rows.rows_px, false,
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - queued_from)
              .count());
      return nullptr;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  last_ = FrameView{};  // the last frame's memory may go with a failing worker
  try {
    // Steps and ray status (with reuse, every pass: the depth) on every sample, so that one
    // kernel serves the whole refinement.
    // Path-traced samples: every pass, for the linear mean that the noise estimate reads.
    const Readback outputs =
        (temporal && !quick) || path_sample ? Readback::Everything : Readback::DisplayAndSteps;
    last_ = filtered
                ? worker_.finish_frame(s, Readback::Everything)
                : worker_.render_frame(slot.scene->info, slot.state, s, plan.sample_index, outputs,
                                       keep || path_sample      ? Readback::Everything
                                       : plan.sample_index == 0 ? Readback::DisplayAndSteps
                                                                : Readback::Display,
                                       band.rows);
  } catch (const RenderWorkerFailure& e) {
    worker_failed(slot, e);
    return nullptr;
  } catch (const std::exception& e) {
    // Said once, not every frame while it keeps failing.
    if (slot.error != e.what()) spdlog::error("{}", e.what());
    slot.error = e.what();
    return nullptr;
  }
  good_scene_id_ = slot.scene->info.id;
  good_state_ = slot.state;
  failed_state_.reset();
  ++frames_rendered_;
  double frame_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (path_sample)
    time_band(filtered ? nullptr : &bands_, filtered ? 0 : band.rows.rows_px, true, frame_ms);
  // (Statistics of the traced frame, before it becomes the shown one; not part of its time.)
  if (plan.sample_index == 0 && last_.steps && last_.pixel_count() > 0) {
    const size_t n = last_.pixel_count();
    double total = 0;
    for (size_t i = 0; i < n; ++i) total += last_.steps[i];
    stats_.de_steps_per_pixel = total / static_cast<double>(n);
    stats_.out_of_steps_fraction = double(count_rays(last_).out_of_steps) / static_cast<double>(n);
    if (count_evaluations_) stats_.eval_counts = worker_.eval_counts();
  }
  if (plan.sample_index == 0 && !plan.done) {
    stats_.temporal = plan.lattice;
    stats_.stride_x = plan.lattice ? phase.stride_x : 1;
    stats_.stride_y = plan.lattice ? phase.stride_y : 1;
    stats_.reuse = ReuseCounts{};
    stats_.compose_ms = 0;
  }
  if (keep && last_.depth && last_.rgba8) {
    // The window's frame: this one's pixels where it traced them, earlier frames' elsewhere.
    const auto compose_start = std::chrono::steady_clock::now();
    const uint8_t* shown = reuse_.compose(
        view_camera_rays(slot.state, window_w, window_h, settings_.render.mirror_vertical,
                         settings_.render.pixel_corners),
        phase, last_.rgba8, last_.depth);
    stats_.reuse = reuse_.counts();
    FrameView composed;
    composed.width_px = window_w;
    composed.height_px = window_h;
    composed.lanes = last_.lanes;
    composed.precision = last_.precision;
    composed.rgba8 = shown;
    last_ = composed;
    stats_.compose_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - compose_start)
            .count();
    frame_ms += stats_.compose_ms;
  } else if (plan.sample_index == 0) {
    reuse_.reset();  // a scaled frame: nothing of it can be carried
  }
  // How far the path-traced view has come, from how much its latest sample moved the mean.
  stats_.path_samples = path_sample ? plan.sample_index + 1 : 0;
  stats_.path_denoised = path_sample && s.denoise;
  if (path_sample && !s.denoise && last_.linear_rgba) {
    const size_t values = 4 * last_.pixel_count();
    if (plan.sample_index == 0) stats_.path_noise.reset();
    if (previous_linear_.size() == values)
      if (const auto e = estimate_noise(previous_linear_.data(), last_.linear_rgba,
                                        last_.pixel_count(), stats_.path_samples))
        stats_.path_noise = e->relative();
    previous_linear_.assign(last_.linear_rgba, last_.linear_rgba + values);
  } else {
    previous_linear_.clear();
    stats_.path_noise.reset();
  }
  stats_.frame_ms = frame_ms;
  if (quick) {
    // Its time is a build's and an unoptimized kernel's: no measure of the frames to come, which
    // start again with the optimized build. That build, and the probe's, happen in the
    // background; until they are done, frames stay quick ones.
    ++quick_frames_rendered_;
    if (!warming_) {
      RenderSettings next = settings_.render;
      next.integrator = Integrator::Fast;
      next.denoise = false;
      next.count_evaluations = count_evaluations_;
      if (!warmup_)
        warmup_ = std::make_unique<KernelWarmup>(worker_.device(), worker_.limits());
      warmup_wanted_ = WarmupJob{slot.scene, slot.state, one_pixel_of(next, window_w, window_h),
                                 temporal_next ? Readback::Everything : Readback::DisplayAndSteps,
                                 to_float3(slot.state.camera.eye)};
      warming_ = true;
    }
  } else {
    frames_.report(stats_.frame_ms);
  }
  stats_.precision = last_.precision;
  stats_.raised_iterations = describe_raised(worker_.raised_iterations());
  return &last_;
}

void Explorer::time_band(SampleBands* bands, int rows, bool read_back, double call_ms) {
  // A queued band starts on the device as the call that queued it returns (that call waited for
  // the band before) and runs while the explorer goes on; the next call waits for it. So the time
  // from one return to the next is the queued band's own when the next call had to wait, and at
  // most that when it did not (the explorer was the slower). A call that reads the frame back
  // waits for its own band (if any) and the read-back as well: timed with the band before (at
  // most), or alone (exactly).
  constexpr double kWaitedMs = 1;  // a call that took longer waited for the device
  const auto now = std::chrono::steady_clock::now();
  const double since_queued_ms =
      std::chrono::duration<double, std::milli>(now - queued_band_at_).count();
  if (queued_band_rows_ > 0 && read_back)
    queued_band_of_->measured(queued_band_rows_ + (bands == queued_band_of_ ? rows : 0),
                              since_queued_ms, true);
  else if (queued_band_rows_ > 0)
    queued_band_of_->measured(queued_band_rows_, since_queued_ms, call_ms < kWaitedMs);
  else if (read_back && bands && rows > 0)
    bands->measured(rows, call_ms, false);
  queued_band_rows_ = read_back ? 0 : rows;
  queued_band_of_ = bands;
  queued_band_at_ = now;
}

std::optional<double> Explorer::depth_under(int x, int y, int width_px, int height_px) {
  if (width_px < 1 || height_px < 1 || x < 0 || y < 0 || x >= width_px || y >= height_px)
    return std::nullopt;
  SceneSlot& slot = current();
  if (took_the_worker_down(slot) || !slot.usable()) return std::nullopt;
  RenderSettings s = settings_.render;
  s.window = ImageWindow{width_px, height_px, x, y, 1, 1};
  s.width_px = s.height_px = 1;
  s.samples = 1;
  s.integrator = Integrator::Fast;  // only the primary march matters
  s.aperture_radius = 0;            // the pixel's own ray, not a lens sample's
  s.denoise = false;                // one pixel (a window)
  // One ray can afford to come closer than a frame's rays do (a tenth of their hit threshold,
  // then plain DE steps towards the surface).
  s.hit_threshold_k *= 0.1f;
  s.refine_steps = 8;
  const FrameView pixel = worker_.render_frame(slot.scene->info, slot.state, s, 0,
                                               Readback::Everything, Readback::Everything);
  const float depth = pixel.depth ? pixel.depth[0] : INFINITY;
  // The worker's accumulation now holds this pixel: the view renders again either way.
  changed_ = true;
  if (!std::isfinite(depth)) return std::nullopt;
  return depth;
}

std::optional<double> Explorer::focus_at(int x, int y, int width_px, int height_px) {
  const std::optional<double> depth = depth_under(x, y, width_px, height_px);
  if (!depth) return std::nullopt;
  // The lens focuses on a plane across the view (kernels/lens.cl): the distance along it.
  const CameraRays rays =
      view_camera_rays(current().state, width_px, height_px, settings_.render.mirror_vertical,
                       settings_.render.pixel_corners);
  const double along = *depth * glm::dot(camera_ray_dir(rays, x, y), rays.forward);
  settings_.render.focus_distance = static_cast<float>(std::clamp(along, 1e-30, 1000.0));
  mark_changed();
  return settings_.render.focus_distance;
}

bool Explorer::took_the_worker_down(const SceneSlot& slot) const {
  return failed_state_ && failed_scene_id_ == slot.scene->info.id &&
         same_state(*failed_state_, slot.state);
}

void Explorer::worker_failed(SceneSlot& slot, const RenderWorkerFailure& failure) {
  const std::string& id = slot.scene->info.id;
  ++worker_failures_;
  spdlog::error("{}", failure.what());
  slot.error = failure.what();
  failed_scene_id_ = id;
  failed_state_ = slot.state;
  changed_ = true;
  scene_changed_ = true;
  if (good_state_ && good_scene_id_ == id) {
    slot.state.params = good_state_->params;  // the parameter that took it down goes back
    slot.state.camera = good_state_->camera;  // and so does the view that did
    spdlog::info("scene '{}': back to the last view and parameters that rendered", id);
  } else if (const int good = library_.find(good_scene_id_); good >= 0 && good != current_) {
    spdlog::info("back to scene '{}', the last one that rendered", good_scene_id_);
    select_scene(good);
  }
}

void Explorer::set_count_evaluations(bool on) {
  if (on == count_evaluations_) return;
  count_evaluations_ = on;
  stats_.eval_counts = EvalCounts{};
  changed_ = true;
}

std::filesystem::path screenshot_view_file(const std::filesystem::path& image) {
  std::filesystem::path view = image;
  return view.replace_extension(".toml");
}

bool Explorer::screenshot(const std::filesystem::path& file, int width_px, int height_px,
                          std::string* error) {
  RenderSettings s = settings_.render;
  s.width_px = width_px;
  s.height_px = height_px;
  s.samples = s.integrator == Integrator::Path ? settings_.explorer.path_samples
                                               : settings_.explorer.full_quality_samples;
  s.denoise = false;  // rendered in bands, below, which the filter cannot take
  SceneSlot& slot = current();
  if (!slot.usable()) {
    *error = "scene '" + slot.scene->info.id + "' " +
             (slot.preparing ? "is still being prepared" : "failed its test render: " + slot.error);
    return false;
  }
  if (width_px < 1 || height_px < 1 || width_px > 65535 || height_px > 65535) {
    *error = "screenshot size " + std::to_string(width_px) + "x" + std::to_string(height_px) +
             " is outside 1 to 65535 pixels a side";
    return false;
  }
  // Rendered like `render` renders a poster: in bands, streamed to the PNG (image/poster.hpp),
  // so a screenshot far larger than the window needs only a band's memory.
  RenderSettings band = s;
  band.height_px = poster_band_rows(width_px, height_px, poster_band_pixels(file));
  const auto need = render_memory_need(band.width_px, band.height_px, is_exr_file_name(file));
  if (const std::string problem = memory_problem(need, worker_.device()); !problem.empty()) {
    *error = "screenshot at " + std::to_string(width_px) + "x" + std::to_string(height_px) + ": " +
             problem;
    return false;
  }
  // The poster's samples replace the view's in the worker: the view refines again afterwards.
  changed_ = true;
  try {
    render_poster(worker_, slot.scene->info, slot.state, s, file, poster_band_pixels(file));
    // The view beside it, every digit of a deep one kept: `--preset shot.toml` opens it again.
    const std::filesystem::path view = screenshot_view_file(file);
    const std::string text = format_preset(
        slot.scene->info, slot.state, slot.scene->info.name + " (screenshot)",
        "The view and parameters of " + file.filename().string() + ".");
    std::string view_error;
    if (view == file)
      spdlog::warn("the screenshot's view is not saved: {} is the image's own name", view.string());
    else if (!write_file_atomic(view, text, &view_error))
      spdlog::warn("the screenshot's view: {}", view_error);
    return true;
  } catch (const RenderWorkerFailure& e) {
    worker_failed(slot, e);
    *error = e.what();
    return false;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}

}  // namespace fr
