// kernel_warmup.hpp — the explorer's next kernels, built in the background.
//
// After edit mode's quick frame (an unoptimized build, on screen within a second) the explorer's
// next frame needs the optimized build of the same kernel, and the probe of the DE at the eye a
// build of its own: 2 to 4 s on two cores, which the frame's thread would spend blocked. A
// warm-up renders one pixel of that next frame, and probes the DE at the eye, in a render worker
// of its own on a thread of its own; the OpenCL compiler's cache keeps what it built, so the
// explorer's own builds of the same kernels, once the warm-up is done, are cache hits. Meanwhile
// the window answers, showing (and flying with) the quick build.
//
// A warm-up that fails (a compile error that only the optimized build meets, a DE that hangs
// there) is not an error of its own: the explorer's own frame meets it and says so, as before.
// Thread: every member is called from the thread that owns the object.
#pragma once

#include "plugin/scene_info.hpp"
#include "worker/render_worker.hpp"

#include <atomic>
#include <memory>
#include <thread>

namespace fr {

struct WarmupJob {
  std::shared_ptr<const LoadedScene> scene;  // kept alive while the warm-up runs
  SceneState state;
  RenderSettings settings;  // as the explorer's next frame's, its size and window included
  Readback outputs = Readback::DisplayAndSteps;
  std::array<float, 3> probe_at{};  // where the explorer probes the DE (the eye)
};

class KernelWarmup {
 public:
  KernelWarmup(const DeviceInfo& device, const RenderWorkerLimits& limits);
  ~KernelWarmup();  // waits for the warm-up under way (at most its worker's limits)
  KernelWarmup(const KernelWarmup&) = delete;
  KernelWarmup& operator=(const KernelWarmup&) = delete;

  // Starts a warm-up; one under way is waited for first (edits come seconds apart).
  void start(WarmupJob job);
  // No warm-up under way (none started, or the last one ended, either way).
  bool done() const { return !running_.load(); }

 private:
  DeviceInfo device_;
  RenderWorkerLimits limits_;
  std::unique_ptr<RenderWorker> worker_;  // started by the first warm-up, used by one at a time
  std::thread thread_;
  std::atomic<bool> running_{false};
};

// The settings of one pixel (the centre) of a width_px x height_px frame rendered with `s`:
// the same kernels and automatic precision as the whole frame, at a pixel's cost.
RenderSettings one_pixel_of(RenderSettings s, int width_px, int height_px);

}  // namespace fr
