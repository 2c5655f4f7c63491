// vet_queue.hpp — the scene library's test renders (render/scene_vetting.hpp) in the background.
//
// On a first start with empty caches, vetting forty scenes takes about half a minute on two cores
// (each test render compiles its kernel). The explorer no longer waits for all of them: the
// queue vets as many files at a time as there are cores (at most 8), the one the user looks at
// first (prioritize), and hands back results as they finish; a scene is used only once its
// result is in. Destroying the queue cancels the test renders under way (their children are
// ended) and drops the rest.
//
// Thread: every member is called from the thread that owns the queue; the vetting threads only
// run vet_scene and post their results.
#pragma once

#include "plugin/plugin_policy.hpp"
#include "render/render_settings.hpp"
#include "render/scene_vetting.hpp"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace fr {

struct VetDone {
  std::filesystem::path file;
  uint64_t hash = 0;  // the content hash the file was queued with
  VetResult result;
};

class VetQueue {
 public:
  // `device`: a selector as for --device ("" for the default). `threads`: how many test renders
  // at once (0: as many as there are cores, at most 8).
  VetQueue(const RenderSettings& settings, std::string device, const PluginPolicy& policy,
           int threads = 0);
  ~VetQueue();
  VetQueue(const VetQueue&) = delete;
  VetQueue& operator=(const VetQueue&) = delete;

  void add(const std::filesystem::path& file, uint64_t hash);
  // Moves `file` to the front of the queue (no effect when it is under way or done).
  void prioritize(const std::filesystem::path& file);
  // The results finished since the last call, in the order they finished.
  std::vector<VetDone> take_done();
  // Blocks until nothing is queued or under way.
  void wait_idle();
  // Files queued or under way.
  int outstanding() const;

 private:
  void run();

  RenderSettings settings_;
  std::string device_;
  PluginPolicy policy_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;  // a job came, or stop
  std::condition_variable idle_;  // a job ended
  std::deque<VetDone> queued_;
  std::vector<VetDone> done_;
  int running_ = 0;
  bool stop_ = false;
  std::atomic<bool> cancel_{false};
  std::vector<std::thread> threads_;
};

}  // namespace fr
