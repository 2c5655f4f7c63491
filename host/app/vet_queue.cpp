#include "app/vet_queue.hpp"

#include <algorithm>

namespace fr {

VetQueue::VetQueue(const RenderSettings& settings, std::string device, const PluginPolicy& policy,
                   int threads)
    : settings_(settings), device_(std::move(device)), policy_(policy) {
  const int count =
      threads > 0 ? threads
                  : static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
  for (int i = 0; i < count; ++i) threads_.emplace_back([this] { run(); });
}

VetQueue::~VetQueue() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    queued_.clear();
  }
  cancel_ = true;
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void VetQueue::add(const std::filesystem::path& file, uint64_t hash) {
  {
    std::lock_guard lock(mutex_);
    queued_.push_back({file, hash, {}});
  }
  wake_.notify_one();
}

void VetQueue::prioritize(const std::filesystem::path& file) {
  std::lock_guard lock(mutex_);
  const auto it = std::find_if(queued_.begin(), queued_.end(),
                               [&](const VetDone& job) { return job.file == file; });
  if (it == queued_.end() || it == queued_.begin()) return;
  VetDone job = std::move(*it);
  queued_.erase(it);
  queued_.push_front(std::move(job));
}

std::vector<VetDone> VetQueue::take_done() {
  std::lock_guard lock(mutex_);
  std::vector<VetDone> out;
  out.swap(done_);
  return out;
}

void VetQueue::wait_idle() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return queued_.empty() && running_ == 0; });
}

int VetQueue::outstanding() const {
  std::lock_guard lock(mutex_);
  return static_cast<int>(queued_.size()) + running_;
}

void VetQueue::run() {
  for (;;) {
    VetDone job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || !queued_.empty(); });
      if (stop_) return;
      job = std::move(queued_.front());
      queued_.pop_front();
      ++running_;
    }
    job.result = vet_scene(job.file, settings_, device_, policy_, &cancel_);
    {
      std::lock_guard lock(mutex_);
      --running_;
      if (!job.result.cancelled) done_.push_back(std::move(job));
    }
    idle_.notify_all();
  }
}

}  // namespace fr
