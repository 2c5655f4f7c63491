#include "app/thumbnail_renderer.hpp"

namespace fr {

ThumbnailRenderer::ThumbnailRenderer(const DeviceInfo& device, const RenderWorkerLimits& limits)
    : device_(device), limits_(limits) {}

ThumbnailRenderer::~ThumbnailRenderer() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    jobs_.clear();
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void ThumbnailRenderer::request(ThumbnailJob job) {
  {
    std::lock_guard lock(mutex_);
    jobs_.push_back(std::move(job));
    // The worker process is started from the thread that uses it, and ends with it.
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  }
  wake_.notify_one();
}

void ThumbnailRenderer::clear() {
  std::lock_guard lock(mutex_);
  jobs_.clear();
}

std::vector<ThumbnailResult> ThumbnailRenderer::take_done() {
  std::lock_guard lock(mutex_);
  return std::exchange(done_, {});
}

bool ThumbnailRenderer::busy() const {
  std::lock_guard lock(mutex_);
  return rendering_ || !jobs_.empty();
}

void ThumbnailRenderer::run() {
  RenderWorker worker(device_, limits_);
  for (;;) {
    ThumbnailJob job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || !jobs_.empty(); });
      if (stop_) return;
      job = std::move(jobs_.back());
      jobs_.pop_back();
      rendering_ = true;
    }
    ThumbnailResult result;
    result.key = job.key;
    try {
      const SceneInfo& info = job.scene->info;
      worker.name_scene_file(info.id, job.scene->file);
      worker.prepare(info, job.state, job.settings);
      FrameImage frame = worker.render(info, job.state, job.settings, false);
      result.image.width_px = frame.width_px;
      result.image.height_px = frame.height_px;
      result.image.rgba8 = std::move(frame.rgba8);
    } catch (const std::exception& e) {
      result.error = e.what();
    }
    std::lock_guard lock(mutex_);
    done_.push_back(std::move(result));
    rendering_ = false;
  }
}

}  // namespace fr
