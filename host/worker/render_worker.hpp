// render_worker.hpp — every OpenCL call that involves a scene's code, in a process of its own.
//
// A scene's DE is OpenCL text that fractalis compiles, and on PoCL the compiled kernel runs in
// the process that launched it: a DE that writes through a bad pointer, recurses without end or
// never returns would take fractalis down or hang it. So, as a browser keeps untrusted GPU work in
// its GPU process, kernel builds, DE probes and renders run in a fractalis-render-worker process;
// fractalis keeps the window, the settings, the files and the user. A worker that crashes, hangs,
// goes over its memory or build-time limit is ended and reaped, the call fails with a
// RenderWorkerFailure naming the scene's file, the stage and the reason, and the next call starts
// a fresh worker. With plugins.isolation = "none" the same calls run in this process (debugging).
//
// Frames come back through shared memory (platform/shared_memory.hpp): the worker reads the
// device's buffers into it, fractalis copies them into the FrameImage (or, for the explorer, reads
// them where they are: render_frame). Output a DE prints (OpenCL printf) goes through a pipe, is
// attributed to the scene and capped.
//
// One RenderWorker is used from one thread, the one that created it (its process is started from
// there: it is killed when that thread ends).
#pragma once

#include "frame_constants.h"
#include "platform/channel.hpp"
#include "plugin/plugin_policy.hpp"
#include "render/cl_runtime.hpp"
#include "render/depth_iterations.hpp"
#include "render/eval_counts.hpp"
#include "render/kernel_assembly.hpp"
#include "render/renderer.hpp"
#include "worker/frame_limit.hpp"
#include "worker/render_wire.hpp"

#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fr {

// The worker ended while doing something for a scene: crashed, hung, over a limit. what() names
// the scene and its file, the stage and the reason.
class RenderWorkerFailure : public std::runtime_error {
 public:
  RenderWorkerFailure(const std::string& what, bool timed_out)
      : std::runtime_error(what), timed_out_(timed_out) {}
  // It went over a time limit (a DE that never returns, a compile that never ends): a command
  // ends with the watchdog's exit status.
  bool timed_out() const { return timed_out_; }

 private:
  bool timed_out_;
};

struct RenderWorkerLimits {
  bool in_process = false;                       // plugins.isolation = "none"
  double start_s = 30;                           // starting the worker and opening the device
  double build_s = 20;                           // one kernel build (plugins.build_timeout_s)
  uint64_t memory_bytes = uint64_t{4096} << 20;  // resident (plugins.worker_memory_mib); 0: none
  FrameLimitRule frame;                          // one sample, one probe
  // The setting behind frame.first_s, named when a sample outlasts it; nullptr: the command's
  // render.watchdog_s, or the explorer's plugins.frame_limit_s.
  const char* frame_setting = nullptr;
  size_t printed_lines = 20;  // lines of a scene's printf output shown
};

// The limits of [plugins] for a command whose samples may take `frame_s` (render.watchdog_s), or
// for the explorer (adaptive, from plugins.frame_limit_s).
RenderWorkerLimits command_worker_limits(const PluginPolicy& policy, double frame_s);
RenderWorkerLimits explorer_worker_limits(const PluginPolicy& policy);

class RenderWorker {
 public:
  // Nothing starts yet: the first call starts the worker on `device`.
  RenderWorker(const DeviceInfo& device, const RenderWorkerLimits& limits);
  ~RenderWorker();  // asks the worker to quit, kills it if it does not, and reaps it
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  const DeviceInfo& device() const { return device_; }
  const RenderWorkerLimits& limits() const { return limits_; }
  // The plugin file a scene id came from, for messages ("scene 'x' (plugins/x.so): ...").
  void name_scene_file(const std::string& scene_id, const std::filesystem::path& file);

  // As Renderer's (render/renderer.hpp), in the worker. Throw KernelBuildError, a
  // std::runtime_error for a device error, or RenderWorkerFailure.
  int lanes_for(const RenderSettings& settings) const;
  Precision prepare(const SceneInfo& info, const SceneState& state, const RenderSettings& settings);
  void render_sample(const SceneInfo& info, const SceneState& state, const RenderSettings& settings,
                     int sample_index, Readback outputs = Readback::Everything, RowBand rows = {});
  void finish(const RenderSettings& settings, Readback what, FrameImage& image);
  // A sample (or its last band of rows) and the frame's read-back in one round trip, with no
  // copy: the explorer's frame. `read` is
  // within what the sample's `outputs` wrote (the view shows the display passes and the depth). The
  // view points into the shared frame (or this object, in process) and is valid until the next call
  // on this RenderWorker.
  FrameView render_frame(const SceneInfo& info, const SceneState& state,
                         const RenderSettings& settings, int sample_index, Readback outputs,
                         Readback read, RowBand rows = {});
  // Renderer::denoise_rows in the worker (queued: the next call waits for it).
  void denoise_rows(const RenderSettings& settings, int pass, RowBand rows);
  // `finish` with no copy, as render_frame reads its frame: the view points into the shared frame
  // and is valid until the next call.
  FrameView finish_frame(const RenderSettings& settings, Readback what);
  FrameImage render(const SceneInfo& info, const SceneState& state, const RenderSettings& settings,
                    bool read_linear = false);
  EvalCounts eval_counts();
  // As render/de_probe.hpp's probe_de.
  std::vector<float> probe_de(const SceneInfo& info, const std::vector<fr_value>& params,
                              const std::vector<std::array<float, 3>>& points, int lanes = 0,
                              Precision precision = Precision::Float,
                              const PairOrigin* origin = nullptr);
  // As render/de_probe.hpp's probe_material.
  std::vector<float> probe_material(const SceneInfo& info, const std::vector<fr_value>& params,
                                    const fr_frame_constants& fc,
                                    const std::vector<std::array<float, 3>>& points);
  // What render.auto_iterations raised for the last view prepared or rendered (empty: nothing;
  // render/depth_iterations.hpp). prepare, render_sample and render_frame render a scene's
  // iteration counts as the view's depth needs, from a probe of the DE at the eye once per view.
  const std::vector<RaisedIterations>& raised_iterations() const { return raised_; }
  // Builds a program of the scene `info` (a check's or a warm-up's), to be found in the cache.
  void build(const SceneInfo& info, const std::string& source, const std::string& options,
             const std::string& description);

  // Workers started so far (a restart after each failure); the current one's pid (0: none).
  int starts() const { return starts_; }
  int64_t pid() const;

 private:
  struct Process;
  struct Local;
  void ensure_started();
  uint64_t send_scene(const SceneInfo& info);
  // A sample's request; notes it as the last sample (its scene, size, the samples' clock).
  void write_sample(WireWriter& w, const SceneInfo& info, const SceneState& state,
                    const RenderSettings& settings, int sample_index, Readback outputs,
                    RowBand rows);
  // Ends `request` (a Finish or RenderFrame) with what to read back, sends it, and returns where
  // the passes lie in the shared frame.
  FramePassPointers finish_in_place(const RenderSettings& settings, Readback what,
                                    WireWriter& request, RenderWireKind kind, int* lanes,
                                    Precision* precision);
  std::string call(uint32_t kind, const std::string& request, const std::string& scene_id,
                   const char* stage, double limit_s);
  [[noreturn]] void fail(const std::string& scene_id, const std::string& stage,
                         const std::string& reason, bool timed_out);
  std::string scene_label(const std::string& scene_id) const;  // "": none
  void drain_output(const std::string& scene_id);

  DeviceInfo device_;
  RenderWorkerLimits limits_;
  FrameLimit frame_limit_;
  std::unique_ptr<Process> process_;
  std::unique_ptr<Local> local_;
  std::map<std::string, std::filesystem::path> scene_files_;
  std::map<std::string, size_t> printed_lines_;  // by scene id
  int starts_ = 0;
  uint64_t last_sample_scene_ = 0;
  double last_sample_pixels_ = 0;
  int pending_samples_ = 0;  // samples asked for since the last finish
  std::chrono::steady_clock::time_point samples_started_;
  std::string last_scene_id_;  // of the last sample: the scene a finish reads back
  // A changed DE's first frame and its probes get at most kFirstLimitOfAnEditS.
  double sample_limit_s() const;
  std::map<std::string, uint64_t> key_of_id_;  // the last scene key sent under each scene id
  // render.auto_iterations: `state`, or the same with its iteration counts raised for its view.
  const SceneState& deepened(const SceneInfo& info, const SceneState& state,
                             const RenderSettings& settings);
  std::string deepened_view_;  // the view deepened_state_ and raised_ were worked out for
  SceneState deepened_state_;
  std::vector<RaisedIterations> raised_;
  std::set<uint64_t> edited_keys_;             // keys sent under an id that had another key before
};

// The limit of a scene's first frame and of its probes, in seconds, when the scene's id was sent
// before under another DE (the explorer's edit mode, a rebuilt plugin): a new scene's first frame
// otherwise gets plugins.frame_limit_s (30 s), and an edit that never returns is said sooner.
constexpr double kFirstLimitOfAnEditS = 10;

// The largest file a worker may write (RLIMIT_FSIZE): a kernel cache entry is a few MB.
constexpr uint64_t kWorkerFileSizeLimitBytes = uint64_t{64} << 20;

// The worker side: what fractalis-render-worker runs. Opens the device `device_selector` (as
// --device takes it), answers on `channel`, reads frames back into the shared frame behind
// `frame_handle`, until told to quit or fractalis goes away. Returns the exit status.
int run_render_worker(Channel& channel, NativeHandle frame_handle,
                      const std::string& device_selector);

}  // namespace fr
