// thumbnail_renderer.hpp — the scene browser's pictures, rendered in the background: a thread of
// its own with a render worker of its own (worker/render_worker.hpp), so the window never waits
// for a kernel build or a slow scene, and a scene that crashes or hangs its worker ends that
// worker only (the picture fails with why; the next one starts a fresh worker).
//
// Jobs are taken newest first (what the user scrolled to last); clear() drops those not started.
// The thread and its worker process start with the first request and end with this object.
#pragma once

#include "image/png_read.hpp"
#include "plugin/scene_info.hpp"
#include "worker/render_worker.hpp"

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace fr {

struct ThumbnailJob {
  std::string key;  // returned with the result
  std::shared_ptr<const LoadedScene> scene;
  SceneState state;
  RenderSettings settings;  // size, samples and everything else of the picture
};

struct ThumbnailResult {
  std::string key;
  RgbaImage image;    // empty on failure
  std::string error;  // why it failed, or ""
};

class ThumbnailRenderer {
 public:
  ThumbnailRenderer(const DeviceInfo& device, const RenderWorkerLimits& limits);
  ~ThumbnailRenderer();  // waits for the picture being rendered (at most its limits), then ends
  ThumbnailRenderer(const ThumbnailRenderer&) = delete;
  ThumbnailRenderer& operator=(const ThumbnailRenderer&) = delete;

  void request(ThumbnailJob job);
  void clear();                              // drops the jobs not started
  std::vector<ThumbnailResult> take_done();  // finished since the last call
  bool busy() const;                         // a job queued or being rendered

 private:
  void run();

  DeviceInfo device_;
  RenderWorkerLimits limits_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<ThumbnailJob> jobs_;
  std::vector<ThumbnailResult> done_;
  bool rendering_ = false;
  bool stop_ = false;
  std::thread thread_;  // started by the first request
};

}  // namespace fr
