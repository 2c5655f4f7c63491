// watchdog.hpp — ending a command that hangs, with a clear error instead of silence.
//
// A scene's DE runs on the OpenCL device, and a DE that never returns makes the kernel never
// finish; no OpenCL call can cancel it. So `render` and `bench` run their rendering
// under a watchdog (`sweep` is interrupted with Ctrl-C instead: its reference renders may
// legitimately take long): when the guarded work has not finished after render.watchdog_s, it
// prints what hung and ends the process (exit status 3). Nothing is half-written: output files are
// written only after rendering, atomically.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace fr {

constexpr int kWatchdogExitStatus = 3;

// A scene whose DE did not return: its test render before the command's own work ran out of
// time (prepared_scene.cpp). Ends the command with kWatchdogExitStatus, as the watchdog would.
struct SceneHangError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// In an MPI job (mpi/shared_tasks.hpp), how long rank 0 waits for a frame or band it handed out
// before it ends the job: the rank's own watchdog ends a task that hangs there after
// `watchdog_s`, and the launcher then ends the job; this catches the rank that cannot (stopped,
// its machine gone) a little later. No limit when the watchdog is off (<= 0).
inline double rank_task_deadline_s(double watchdog_s) {
  return watchdog_s > 0 ? watchdog_s + 10 : 0;
}

class Watchdog {
 public:
  // Starts guarding; `limit_s` <= 0 guards nothing. `what` completes "... did not finish
  // within N s" ("rendering scene 'menger' at 1920x1080").
  Watchdog(double limit_s, std::string what);
  ~Watchdog();  // the guarded work finished
  // One image finished: the limit starts again for the next one.
  void kick();
  // The guarded work finished (as the destructor, earlier).
  void stop();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = false;
  std::chrono::steady_clock::time_point deadline_;
  std::chrono::steady_clock::duration limit_{};
  std::thread thread_;
};

}  // namespace fr
