#include "cli/watchdog.hpp"

#include "io/atomic_file.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace fr {

Watchdog::Watchdog(double limit_s, std::string what) {
  if (!(limit_s > 0)) return;
  limit_ = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(limit_s));
  deadline_ = std::chrono::steady_clock::now() + limit_;
  thread_ = std::thread([this, limit_s, what = std::move(what)] {
    std::unique_lock lock(mutex_);
    for (;;) {
      const auto deadline = deadline_;
      if (done_cv_.wait_until(lock, deadline, [&] { return done_ || deadline_ != deadline; })) {
        if (done_) return;
        continue;  // kicked: wait for the new deadline
      }
      break;
    }
    // The work is stuck inside a call nothing can interrupt; say so, and end the process.
    std::fprintf(stderr,
                 "fractalis: error: %s did not finish within %g s (render.watchdog_s); the "
                 "scene's DE may never return for some points. Nothing half-written is left.\n",
                 what.c_str(), limit_s);
    std::fflush(stderr);
    remove_temp_files();              // a poster's or a video's file in progress
    std::_Exit(kWatchdogExitStatus);  // no destructors: other threads are still running
  });
}

void Watchdog::kick() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    deadline_ = std::chrono::steady_clock::now() + limit_;
  }
  done_cv_.notify_all();
}

Watchdog::~Watchdog() {
  stop();
}

void Watchdog::stop() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  done_cv_.notify_all();
  thread_.join();
}

}  // namespace fr
