// progress.hpp — how long commands report how far they are: a bar redrawn in place on a terminal
// ("[#######.......] frame 12/49, 31 s left"), plain lines otherwise (a log file or a CI console
// gets lines, not carriage returns): one per step, at most about a hundred in all (one per 1% of
// the steps, or one per 10 s when steps are slow), and always the last.
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

namespace fr {

class Progress {
 public:
  // `noun` names a step ("frame", "band"); `already_done` steps were done before this run (a
  // resumed sequence) and do not count towards the time-left estimate.
  Progress(std::ostream& err, std::string noun, int total, int already_done = 0);
  void update(int done);
  // Ends the bar's line on a terminal.
  void finish();

 private:
  std::ostream& err_;
  std::string noun_;
  int total_, already_done_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  int last_line_done_ = -1;  // the step of the last plain line
  double last_line_s_ = 0;
};

}  // namespace fr
