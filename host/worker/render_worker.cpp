#include "worker/render_worker.hpp"

#include "io/build_paths.hpp"
#include "io/helper_executable.hpp"
#include "io/printable.hpp"
#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "platform/shared_memory.hpp"
#include "plugin/wire_io.hpp"
#include "render/de_probe.hpp"
#include "worker/render_wire.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <fstream>
#include <sstream>
#include <thread>

namespace fr {
namespace {

// What both probes start with (render_worker_serve.cpp's read_probe_request).
WireWriter probe_request(uint64_t key, const std::vector<fr_value>& params,
                         const std::vector<std::array<float, 3>>& points) {
  WireWriter w;
  w.u64(key);
  w.u32(static_cast<uint32_t>(params.size()));
  w.raw(params.data(), params.size() * sizeof(fr_value));
  w.u32(static_cast<uint32_t>(points.size()));
  w.raw(points.data(), points.size() * sizeof(points[0]));
  return w;
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string seconds_text(double s) {
  std::ostringstream out;
  out << s << " s";
  return out.str();
}

constexpr const char* kFrameStage = "rendering";

}  // namespace

RenderWorkerLimits command_worker_limits(const PluginPolicy& policy, double frame_s) {
  RenderWorkerLimits l;
  l.in_process = policy.isolation == PluginIsolation::None;
  l.build_s = policy.build_timeout_s;
  l.memory_bytes = static_cast<uint64_t>(policy.worker_memory_mib) << 20;
  l.frame.adaptive = false;
  l.frame.first_s = frame_s;
  return l;
}

RenderWorkerLimits explorer_worker_limits(const PluginPolicy& policy) {
  RenderWorkerLimits l = command_worker_limits(policy, policy.frame_limit_s);
  l.frame.adaptive = true;
  return l;
}

// The worker process and what it has been sent.
struct RenderWorker::Process {
  std::unique_ptr<ChildProcess> child;
  Channel channel;
  Channel output;      // its stdout (a DE's printf), ours to read; closed once it closed
  SharedMemory frame;  // the frames read back (never shrinks under us)
  // What it holds, oldest first (at most kWorkerSceneCount): each scene's key and bytes, so that
  // a scene whose key another's hash already took replaces it rather than being mistaken for it.
  std::deque<std::pair<uint64_t, std::string>> scenes;
  std::string partial_line;  // output not yet ended by a newline

  // Ends the process (killed unless it has exited by itself within `grace_ms`) and reaps it;
  // returns how it ended when it ended by itself.
  std::string end(int grace_ms) {
    if (!child || child->ended()) return "";
    if (child->wait(grace_ms)) return child->how_it_ended();
    child->kill();
    return "";
  }
};

// plugins.isolation = "none": the device in this process.
struct RenderWorker::Local {
  explicit Local(const DeviceInfo& device) : runtime(device), renderer(runtime) {}
  ClRuntime runtime;
  Renderer renderer;
  FrameImage image;  // render_frame's
};

RenderWorker::RenderWorker(const DeviceInfo& device, const RenderWorkerLimits& limits)
    : device_(device), limits_(limits), frame_limit_(limits.frame) {}

RenderWorker::~RenderWorker() {
  if (process_) {
    write_frame(process_->channel, static_cast<WireKind>(RenderWireKind::Quit), "");
    process_->channel.close();
    process_->end(200);
  }
}

int64_t RenderWorker::pid() const {
  return process_ && process_->child ? process_->child->id() : 0;
}

void RenderWorker::name_scene_file(const std::string& scene_id, const std::filesystem::path& file) {
  scene_files_[scene_id] = file;
}

int RenderWorker::lanes_for(const RenderSettings& settings) const {
  return resolve_lanes(settings.lanes, &device_, settings.precision);
}

std::string RenderWorker::scene_label(const std::string& scene) const {
  if (scene.empty()) return "the render worker";
  std::string label = "scene '" + scene + "'";
  if (const auto it = scene_files_.find(scene); it != scene_files_.end())
    label += " (" + it->second.string() + ")";
  return label;
}

void RenderWorker::fail(const std::string& scene, const std::string& stage,
                        const std::string& reason, bool timed_out) {
  pending_samples_ = 0;
  if (process_) {
    drain_output(scene);
    process_->end(0);
    process_.reset();
  }
  const std::string who =
      scene.empty() ? "the render worker" : scene_label(scene) + ": the render worker";
  const bool started = stage != "starting";
  throw RenderWorkerFailure(
      who + " " + reason + " while " + stage +
          (started ? "; it was ended (the next render starts a fresh one)" : ""),
      timed_out);
}

void RenderWorker::ensure_started() {
  if (limits_.in_process) {
    if (!local_) local_ = std::make_unique<Local>(device_);
    return;
  }
  if (process_) return;
  const std::filesystem::path exe = helper_executable(
      "fractalis-render-worker", "FRACTALIS_RENDER_WORKER", build_paths::render_worker);
  if (exe.empty())
    throw std::runtime_error(
        "the render worker executable fractalis-render-worker was not found (beside fractalis, "
        "in ../libexec/fractalis, or $FRACTALIS_RENDER_WORKER)");
  auto p = std::make_unique<Process>();
  ChannelPair channel, output;
  std::string error;
  if (!make_channel_pair(&channel, &error) || !make_pipe(&output, &error))
    throw std::runtime_error("cannot connect to the render worker: " + error);
  p->channel = std::move(channel.ours);
  p->output = std::move(output.ours);
  ChildSpec spec;
  spec.program = exe;
  spec.handles = {channel.theirs.handle(), p->frame.handle()};
  spec.arguments = {"--wire",    std::to_string(kRenderWireVersion),
                    "--device",  device_.selector(),
                    "--channel", handle_in_child(0, spec.handles[0]),
                    "--frame",   handle_in_child(1, spec.handles[1])};
  spec.stdout_to = output.theirs.handle();
  spec.stderr_to = own_stderr();
  p->child = ChildProcess::start(spec, &error);
  if (!p->child) throw std::runtime_error("cannot start the render worker: " + error);
  process_ = std::move(p);
  ++starts_;
  call(static_cast<uint32_t>(RenderWireKind::Ready), "", "", "starting", limits_.start_s);
}

void RenderWorker::drain_output(const std::string& scene) {
  if (!process_ || !process_->output.is_open()) return;
  char buffer[65536];
  for (;;) {
    size_t got = 0;
    const ChannelStatus s = process_->output.read_some(buffer, sizeof buffer, 0, &got);
    if (s != ChannelStatus::Ok) {
      if (s == ChannelStatus::Closed) process_->output.close();  // the worker is ending
      return;
    }
    size_t& shown = printed_lines_[scene];
    for (size_t i = 0; i < got; ++i) {
      std::string& line = process_->partial_line;
      const bool end = buffer[i] == '\n';
      if (!end) line.push_back(buffer[i]);
      if (!end && line.size() < 240) continue;
      if (shown < limits_.printed_lines)
        spdlog::warn("{} printed: {}", scene_label(scene), printable(line));
      else if (shown == limits_.printed_lines)
        spdlog::warn("{} printed more than {} lines; the rest of its output is not shown",
                     scene_label(scene), limits_.printed_lines);
      if (shown <= limits_.printed_lines) ++shown;
      line.clear();
    }
  }
}

std::string RenderWorker::call(uint32_t kind, const std::string& request, const std::string& scene,
                               const char* stage, double limit_s) {
  Process& p = *process_;
  std::string building;  // the kernel being built, while one is
  const auto now_doing = [&] {
    return building.empty() ? std::string(stage) : "compiling " + building;
  };
  const auto ended = [&](const std::string& fallback) {
    const std::string how = process_->end(500);
    fail(scene, now_doing(), how.empty() ? fallback : how, false);
  };
  if (kind != static_cast<uint32_t>(RenderWireKind::Ready) &&
      !write_frame(p.channel, static_cast<WireKind>(kind), request))
    ended("closed its connection");
  auto deadline = Clock::now();
  const auto restart_clock = [&](double s) {
    deadline = s > 0 ? Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(s))
                     : Clock::time_point::max();
  };
  restart_clock(limit_s);
  auto last_memory_check = Clock::now();
  for (;;) {
    const double left_s = deadline == Clock::time_point::max()
                              ? 1e9
                              : std::chrono::duration<double>(deadline - Clock::now()).count();
    if (left_s <= 0) {
      if (!building.empty())
        fail(
            scene, "compiling " + building,
            "did not finish within " + seconds_text(limits_.build_s) + " (plugins.build_timeout_s)",
            true);
      std::string which;  // the setting behind the limit
      if (limit_s == limits_.frame.first_s)
        which = limits_.frame_setting    ? " (" + std::string(limits_.frame_setting) + ")"
                : limits_.frame.adaptive ? " (plugins.frame_limit_s)"
                                         : " (render.watchdog_s)";
      else if (limit_s == kFirstLimitOfAnEditS && stage == std::string("probing the DE"))
        which = " (a changed DE's probe)";
      else if (limit_s == kFirstLimitOfAnEditS && stage == std::string(kFrameStage))
        which = " (a changed DE's first frame)";
      else if (limits_.frame.adaptive && stage != std::string("starting"))
        which = " (the scene's slowest time per pixel so far, times 20)";
      fail(scene, stage, "did not finish within " + seconds_text(limit_s) + which, true);
    }
    Channel* const both[2] = {&p.channel, &p.output};
    // A quick answer (a DE probe, a queued sample) comes within tens of microseconds: looking
    // for it for a moment costs less than sleeping in the system and being woken.
    int ready = -1;
    for (const auto spin_until = Clock::now() + std::chrono::microseconds(150);
         ready < 0 && Clock::now() < spin_until;)
      ready = wait_readable(both, 2, 0);
    // Then short waits: the worker's memory is looked at between them.
    const int wait_ms = static_cast<int>(std::ceil(std::min(left_s, 0.1) * 1000));
    if (ready < 0) ready = wait_readable(both, 2, wait_ms);
    if (ready == 1) drain_output(scene);
    if (limits_.memory_bytes > 0 && seconds_since(last_memory_check) >= 0.1) {
      last_memory_check = Clock::now();
      if (p.child->resident_bytes() > limits_.memory_bytes)
        fail(scene, now_doing(),
             "used more than " + std::to_string(limits_.memory_bytes >> 20) +
                 " MiB of memory (plugins.worker_memory_mib)",
             false);
    }
    if (ready != 0) continue;
    WireKind got{};
    std::string payload;
    const ReadStatus s = read_frame_exact(p.channel, std::max(1.0, left_s), &got, &payload);
    if (s == ReadStatus::Closed) ended("closed its connection");
    if (s == ReadStatus::TimedOut) continue;
    if (s != ReadStatus::Ok) fail(scene, now_doing(), "sent a malformed message", false);
    WireReader r(payload);
    const auto got_kind = static_cast<RenderWireKind>(got);
    if (got_kind == RenderWireKind::Building) {
      const bool starts = r.u32() != 0;
      building = starts ? printable(r.str(kMaxWorkerErrorBytes)) : "";
      if (r.failed()) fail(scene, stage, "sent a malformed message", false);
      restart_clock(starts ? limits_.build_s : limit_s);
      continue;
    }
    const bool expected =
        got_kind == RenderWireKind::Reply ||
        (kind == static_cast<uint32_t>(RenderWireKind::Ready) && got_kind == RenderWireKind::Ready);
    if (!expected) fail(scene, stage, "sent a message out of turn", false);
    const auto status = static_cast<ReplyStatus>(r.u32());
    const std::string error = r.str(kMaxWorkerErrorBytes);
    if (r.failed()) fail(scene, stage, "sent a malformed reply", false);
    drain_output(scene);
    if (status == ReplyStatus::Ok) return std::string(r.rest());
    if (kind == static_cast<uint32_t>(RenderWireKind::Ready)) {
      process_->end(500);
      process_.reset();
      throw std::runtime_error("the render worker could not open device " + device_.name + ": " +
                               error);
    }
    if (status == ReplyStatus::BuildFailed) throw KernelBuildError(error);
    throw std::runtime_error(error);
  }
}

uint64_t RenderWorker::send_scene(const SceneInfo& info) {
  // Every call names its scene, so this runs once a frame or more: std::hash reads a scene's
  // bytes (its DE source, ~10 KB) eight times faster than FNV-1a.
  WireWriter scene;
  write_scene_info(scene, info);
  const uint64_t key = std::max<uint64_t>(1, std::hash<std::string>{}(scene.bytes()));  // 0: none
  if (const auto [known, fresh] = key_of_id_.try_emplace(info.id, key);
      !fresh && known->second != key) {
    edited_keys_.insert(key);
    known->second = key;
  }
  auto& held = process_->scenes;
  const auto same_key =
      std::find_if(held.begin(), held.end(), [&](const auto& h) { return h.first == key; });
  if (same_key != held.end() && same_key->second == scene.bytes()) return key;
  uint64_t forget = 0;
  if (same_key != held.end()) {
    forget = key;
    held.erase(same_key);
  } else if (held.size() >= kWorkerSceneCount) {
    forget = held.front().first;
  }
  WireWriter w;
  w.u64(key);
  w.u64(forget);
  w.raw(scene.bytes().data(), scene.bytes().size());
  call(static_cast<uint32_t>(RenderWireKind::SetScene), w.bytes(), info.id, "receiving the scene",
       limits_.start_s);
  if (forget != 0 && forget != key) held.pop_front();
  held.emplace_back(key, scene.bytes());
  return key;
}

const SceneState& RenderWorker::deepened(const SceneInfo& info, const SceneState& state,
                                         const RenderSettings& settings) {
  if (!settings.auto_iterations ||
      std::none_of(info.params.begin(), info.params.end(),
                   [](const ParamInfo& p) { return p.detail_ratio > 0; })) {
    raised_.clear();
    return state;
  }
  // The view: the scene, its camera (with the digits past double), its parameters and the
  // image's size; probed once, then every sample and band of it reuses the answer.
  std::string view = info.id + '\n' + std::to_string(settings.width_px) + 'x' +
                     std::to_string(settings.height_px) + '\n' + std::to_string(state.bounding_radius);
  const auto add = [&view](const void* p, size_t n) {
    view.append(static_cast<const char*>(p), n);
  };
  add(&state.camera, sizeof state.camera);
  add(&state.camera_lo, sizeof state.camera_lo);
  for (const fr_value& v : state.params) add(&v, sizeof v);
  if (view != deepened_view_) {
    const DeProbe probe = [&](const std::vector<fr_value>& params,
                              const std::vector<std::array<float, 3>>& points, Precision precision,
                              const PairOrigin* origin) {
      return probe_de(info, params, points, 1, precision, origin);
    };
    std::vector<fr_value> raised_params;
    raised_ = raise_iterations_for_view(probe, info, state, settings.width_px, settings.height_px,
                                        device_.has_fp64, raised_params);
    deepened_view_ = std::move(view);
  }
  if (std::none_of(raised_.begin(), raised_.end(),
                   [](const RaisedIterations& r) { return r.used > r.set; }))
    return state;
  // This call's state (its time, lights and the rest are this frame's) with the counts raised.
  deepened_state_ = state;
  for (const RaisedIterations& r : raised_)
    if (const int i = info.find_param(r.key); i >= 0) deepened_state_.params[i].v[0] = r.used;
  return deepened_state_;
}

Precision RenderWorker::prepare(const SceneInfo& info, const SceneState& requested,
                                const RenderSettings& settings) {
  ensure_started();
  const SceneState& state = deepened(info, requested, settings);
  if (local_) return local_->renderer.prepare(info, state, settings);
  WireWriter w;
  w.u64(send_scene(info));
  write_scene_state(w, state);
  write_render_settings(w, settings);
  const std::string reply = call(static_cast<uint32_t>(RenderWireKind::Prepare), w.bytes(), info.id,
                                 "preparing", limits_.build_s);
  WireReader r(reply);
  const uint32_t precision = r.u32();
  if (r.failed() || !resolved_precision(precision))
    fail(info.id, "preparing", "sent a malformed reply", false);
  return static_cast<Precision>(precision);
}

void RenderWorker::write_sample(WireWriter& w, const SceneInfo& info, const SceneState& state,
                                const RenderSettings& settings, int sample_index, Readback outputs,
                                RowBand rows) {
  const uint64_t key = send_scene(info);
  w.u64(key);
  write_scene_state(w, state);
  write_render_settings(w, settings);
  w.i32(sample_index);
  w.u32(static_cast<uint32_t>(outputs));
  w.i32(rows.first_row_px);
  w.i32(rows.rows_px);
  if (pending_samples_ == 0) samples_started_ = Clock::now();
  last_scene_id_ = info.id;
  // The limit follows the pixels this call renders (a band's, of a banded sample).
  last_sample_pixels_ = static_cast<double>(settings.width_px) *
                        (rows.rows_px > 0 ? rows.rows_px : settings.height_px);
  last_sample_scene_ = key;
}

double RenderWorker::sample_limit_s() const {
  const double limit_s = frame_limit_.limit_s(last_sample_scene_, last_sample_pixels_);
  if (edited_keys_.count(last_sample_scene_) && !frame_limit_.knows(last_sample_scene_) &&
      (limit_s <= 0 || limit_s > kFirstLimitOfAnEditS))
    return kFirstLimitOfAnEditS;
  return limit_s;
}

void RenderWorker::render_sample(const SceneInfo& info, const SceneState& requested,
                                 const RenderSettings& settings, int sample_index, Readback outputs,
                                 RowBand rows) {
  ensure_started();
  const SceneState& state = deepened(info, requested, settings);
  if (local_)
    return local_->renderer.render_sample(info, state, settings, sample_index, outputs, rows);
  WireWriter w;
  write_sample(w, info, state, settings, sample_index, outputs, rows);
  // The worker answers once the sample is queued; this call also waits for the sample before
  // (its upload is a blocking write), and `finish` for the last: each within one sample's limit.
  call(static_cast<uint32_t>(RenderWireKind::RenderSample), w.bytes(), info.id, kFrameStage,
       sample_limit_s());
  ++pending_samples_;
}

FramePassPointers RenderWorker::finish_in_place(const RenderSettings& settings, Readback what,
                                                WireWriter& request, RenderWireKind kind,
                                                int* lanes, Precision* precision) {
  const size_t n = static_cast<size_t>(settings.width_px) * settings.height_px;
  size_t bytes = 0;
  frame_passes_at(nullptr, n, what, &bytes);
  process_->frame.grow(bytes);
  request.u32(static_cast<uint32_t>(what));
  request.u64(bytes);
  const std::string reply = call(static_cast<uint32_t>(kind), request.bytes(), last_scene_id_,
                                 kFrameStage, sample_limit_s());
  // The samples' mean time (kernel builds included: that only makes later limits longer).
  if (pending_samples_ > 0)
    frame_limit_.record(last_sample_scene_, last_sample_pixels_,
                        seconds_since(samples_started_) / pending_samples_);
  pending_samples_ = 0;
  WireReader r(reply);
  *lanes = r.i32();
  const uint32_t p = r.u32();
  if (r.failed() || !resolved_precision(p))
    fail(last_scene_id_, "reading back a frame", "sent a malformed reply", false);
  *precision = static_cast<Precision>(p);
  return frame_passes_at(process_->frame.data(), n, what, &bytes);
}

void RenderWorker::finish(const RenderSettings& settings, Readback what, FrameImage& image) {
  ensure_started();
  if (local_) return local_->renderer.finish(settings, what, image);
  WireWriter w;
  write_render_settings(w, settings);
  const FramePassPointers from =
      finish_in_place(settings, what, w, RenderWireKind::Finish, &image.lanes, &image.precision);
  const FramePassPointers to = size_frame_image(image, settings.width_px, settings.height_px, what);
  const size_t n = static_cast<size_t>(settings.width_px) * settings.height_px;
  const auto copy = [](void* dst, const void* src, size_t count) {
    if (dst && src) std::memcpy(dst, src, count);
  };
  copy(to.rgba8, from.rgba8, n * 4);
  copy(to.steps, from.steps, n * 4);
  copy(to.ray_status, from.ray_status, n);
  copy(to.linear_rgba, from.linear_rgba, n * 16);
  copy(to.depth, from.depth, n * 4);
  copy(to.occlusion, from.occlusion, n * 4);
  copy(to.shadow, from.shadow, n * 4);
  copy(to.normal, from.normal, n * 12);
  copy(to.albedo, from.albedo, n * 12);
}

namespace {

// A frame view of the passes the explorer reads, where they lie in the shared frame.
void point_view_at(FrameView& view, const FramePassPointers& at) {
  view.rgba8 = at.rgba8;
  view.steps = at.steps;
  view.ray_status = at.ray_status;
  view.depth = at.depth;
  view.linear_rgba = at.linear_rgba;
}

}  // namespace

void RenderWorker::denoise_rows(const RenderSettings& settings, int pass, RowBand rows) {
  ensure_started();
  if (local_) return local_->renderer.denoise_rows(settings, pass, rows);
  WireWriter w;
  write_render_settings(w, settings);
  w.i32(pass);
  w.i32(rows.first_row_px);
  w.i32(rows.rows_px);
  call(static_cast<uint32_t>(RenderWireKind::DenoiseRows), w.bytes(), last_scene_id_, kFrameStage,
       sample_limit_s());
}

FrameView RenderWorker::finish_frame(const RenderSettings& settings, Readback what) {
  ensure_started();
  FrameView view;
  view.width_px = settings.width_px;
  view.height_px = settings.height_px;
  if (local_) {
    local_->renderer.finish(settings, what, local_->image);
    return view_of(local_->image);
  }
  WireWriter w;
  write_render_settings(w, settings);
  const FramePassPointers at =
      finish_in_place(settings, what, w, RenderWireKind::Finish, &view.lanes, &view.precision);
  point_view_at(view, at);
  return view;
}

FrameView RenderWorker::render_frame(const SceneInfo& info, const SceneState& requested,
                                     const RenderSettings& settings, int sample_index,
                                     Readback outputs, Readback read, RowBand rows) {
  if (static_cast<int>(read) > static_cast<int>(outputs))
    throw std::logic_error("RenderWorker::render_frame: reads the passes the sample wrote");
  ensure_started();
  const SceneState& state = deepened(info, requested, settings);
  FrameView view;
  view.width_px = settings.width_px;
  view.height_px = settings.height_px;
  if (local_) {
    local_->renderer.render_sample(info, state, settings, sample_index, outputs, rows);
    local_->renderer.finish(settings, read, local_->image);
    return view_of(local_->image);
  }
  WireWriter w;
  write_sample(w, info, state, settings, sample_index, outputs, rows);
  ++pending_samples_;
  const FramePassPointers at =
      finish_in_place(settings, read, w, RenderWireKind::RenderFrame, &view.lanes, &view.precision);
  point_view_at(view, at);
  return view;
}

FrameImage RenderWorker::render(const SceneInfo& info, const SceneState& state,
                                const RenderSettings& settings, bool read_linear) {
  return render_all_samples(*this, info, state, settings, read_linear);
}

EvalCounts RenderWorker::eval_counts() {
  ensure_started();
  if (local_) return local_->renderer.eval_counts();
  static_assert(std::is_trivially_copyable_v<EvalCounts>);
  const std::string reply = call(static_cast<uint32_t>(RenderWireKind::EvalCounts), "",
                                 last_scene_id_, "reading the DE counters", limits_.start_s);
  EvalCounts counts;
  WireReader r(reply);
  if (!r.raw(&counts, sizeof counts) || counts.lanes < 1 || counts.lanes > 64)
    fail(last_scene_id_, "reading the DE counters", "sent a malformed reply", false);
  return counts;
}

std::vector<float> RenderWorker::probe_de(const SceneInfo& info,
                                          const std::vector<fr_value>& params,
                                          const std::vector<std::array<float, 3>>& points,
                                          int lanes, Precision precision,
                                          const PairOrigin* origin) {
  ensure_started();
  if (local_) return fr::probe_de(local_->runtime, info, params, points, lanes, precision, origin);
  const uint64_t key = send_scene(info);
  WireWriter w = probe_request(key, params, points);
  w.i32(lanes);
  w.u32(static_cast<uint32_t>(precision));
  const PairOrigin none{};
  const PairOrigin& o = origin ? *origin : none;
  for (const DoubleDouble& c : o.eye) {
    w.f64(c.hi);
    w.f64(c.lo);
  }
  w.f64(o.resolution_rad);
  // A changed DE's probe gets 10 s, not a new scene's first-sample limit: a probe is a few
  // points, so an edit that never returns is said within seconds.
  double limit_s = frame_limit_.limit_s(key, static_cast<double>(points.size()));
  if (edited_keys_.count(key) && (limit_s <= 0 || limit_s > kFirstLimitOfAnEditS))
    limit_s = kFirstLimitOfAnEditS;
  const std::string reply = call(static_cast<uint32_t>(RenderWireKind::Probe), w.bytes(), info.id,
                                 "probing the DE", limit_s);
  WireReader r(reply);
  const uint32_t count = r.u32();
  std::vector<float> values(points.size());
  if (count != points.size() || !r.raw(values.data(), values.size() * sizeof(float)))
    fail(info.id, "probing the DE", "sent a malformed reply", false);
  return values;
}

std::vector<float> RenderWorker::probe_material(const SceneInfo& info,
                                                const std::vector<fr_value>& params,
                                                const fr_frame_constants& fc,
                                                const std::vector<std::array<float, 3>>& points) {
  ensure_started();
  if (local_) return fr::probe_material(local_->runtime, info, params, fc, points);
  const uint64_t key = send_scene(info);
  WireWriter w = probe_request(key, params, points);
  w.raw(&fc, sizeof fc);
  const double limit_s = frame_limit_.limit_s(key, static_cast<double>(points.size()));
  const std::string reply = call(static_cast<uint32_t>(RenderWireKind::ProbeMaterial), w.bytes(),
                                 info.id, "probing the material function", limit_s);
  WireReader r(reply);
  const uint32_t count = r.u32();
  std::vector<float> values(points.size() * kMaterialFloats);
  if (count != values.size() || !r.raw(values.data(), values.size() * sizeof(float)))
    fail(info.id, "probing the material function", "sent a malformed reply", false);
  return values;
}

void RenderWorker::build(const SceneInfo& info, const std::string& source,
                         const std::string& options, const std::string& description) {
  ensure_started();
  if (local_) {
    local_->runtime.program(source, options, description);
    return;
  }
  WireWriter w;
  w.str(source);
  w.str(options);
  w.str(description);
  call(static_cast<uint32_t>(RenderWireKind::Build), w.bytes(), info.id, "compiling",
       limits_.build_s);
}

}  // namespace fr
