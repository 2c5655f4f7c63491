#include "app/kernel_warmup.hpp"

#include <spdlog/spdlog.h>

namespace fr {

KernelWarmup::KernelWarmup(const DeviceInfo& device, const RenderWorkerLimits& limits)
    : device_(device), limits_(limits) {}

KernelWarmup::~KernelWarmup() {
  if (thread_.joinable()) thread_.join();
}

void KernelWarmup::start(WarmupJob job) {
  if (thread_.joinable()) thread_.join();
  if (!worker_) worker_ = std::make_unique<RenderWorker>(device_, limits_);
  running_ = true;
  thread_ = std::thread([this, job = std::move(job)] {
    try {
      const SceneInfo& info = job.scene->info;
      worker_->name_scene_file(info.id, job.scene->file);
      worker_->render_frame(info, job.state, job.settings, 0, job.outputs, Readback::Display);
      worker_->probe_de(info, job.state.params, {job.probe_at});
    } catch (const std::exception& e) {
      // The explorer's own frame meets the same problem and says it (kernel_warmup.hpp).
      spdlog::debug("kernel warm-up: {}", e.what());
    }
    running_ = false;
  });
}

RenderSettings one_pixel_of(RenderSettings s, int width_px, int height_px) {
  s.window = ImageWindow{width_px, height_px, width_px / 2, height_px / 2, 1, 1};
  s.width_px = s.height_px = 1;
  return s;
}

}  // namespace fr
