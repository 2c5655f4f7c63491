// progress.hpp — how long commands report how far they are: a bar redrawn in place on a terminal
// ("[#######.......] frame 12/49, 31 s left"), plain lines otherwise (a log file or a CI console
// gets lines, not carriage returns): one per step, at most about a hundred in all (one per 1% of
// the steps, or one per 10 s when steps are slow), and always the last.
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

namespace fr {

// The one progress display of `render`, `animate` and `sweep`.
class Progress {
 public:
  // `noun` names a step ("frame", "band", "step"); `already_done` steps were done before this
  // run (a resumed sequence) and do not count towards the time-left estimate. `terminal`: draw
  // a bar (the default asks whether stderr is a terminal).
  Progress(std::ostream& err, std::string noun, int total, int already_done = 0);
  Progress(std::ostream& err, std::string noun, int total, int already_done, bool terminal);
  // `detail` says what the step is ("measuring max_steps=80").
  void update(int done, const std::string& detail = "");
  // Ends the bar's line on a terminal (before a warning, or at the end); the next update draws
  // a new bar.
  void finish();

 private:
  std::ostream& err_;
  std::string noun_;
  int total_, already_done_;
  bool terminal_;
  bool bar_drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  int last_line_done_ = -1;  // the step of the last plain line
  double last_line_s_ = 0;
};

}  // namespace fr
