// interrupt.hpp — Ctrl-C, and the other ways a user or the system asks a console program to end
// (SIGTERM and SIGHUP; Ctrl-Break and the console window closing on Windows).
#pragma once

namespace fr {

// While one lives, such a request sets interrupted() instead of ending the process, and the
// previous handling comes back when it ends. One at a time, from the main thread.
class InterruptCatcher {
 public:
  InterruptCatcher();
  ~InterruptCatcher();
  InterruptCatcher(const InterruptCatcher&) = delete;
  InterruptCatcher& operator=(const InterruptCatcher&) = delete;
  static bool interrupted();
};

// Runs `last_words` when such a request is about to end the process, then lets it end as it
// would have (the status says it was interrupted). Only where nothing else handles the request
// already (a shell's nohup keeps its own). `last_words` may run in a signal handler (POSIX) or
// on a thread of its own (Windows): async-signal-safe calls only, no allocation, no locks.
void on_termination_request(void (*last_words)());

}  // namespace fr
