// progress.hpp — how long commands report how far they are: a bar redrawn in place on a terminal
// ("[#######.......] frame 12/49, 31 s left"), one plain line per step otherwise (a log file or a
// CI console gets lines, not carriage returns).
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
};

}  // namespace fr
