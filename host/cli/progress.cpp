#include "cli/progress.hpp"

#include "platform/terminal.hpp"

#include <algorithm>
#include <ostream>

namespace fr {

Progress::Progress(std::ostream& err, std::string noun, int total, int already_done)
    : Progress(err, std::move(noun), total, already_done, stderr_is_terminal()) {}

Progress::Progress(std::ostream& err, std::string noun, int total, int already_done, bool terminal)
    : err_(err),
      noun_(std::move(noun)),
      total_(std::max(total, 1)),
      already_done_(already_done),
      terminal_(terminal),
      start_(std::chrono::steady_clock::now()) {}

void Progress::update(int done, const std::string& detail) {
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const int done_now = done - already_done_;
  const int left_s =
      done_now > 0 ? static_cast<int>(elapsed_s / done_now * (total_ - done) + 0.5) : 0;
  const std::string status = noun_ + " " + std::to_string(done) + "/" + std::to_string(total_) +
                             (detail.empty() ? "" : ": " + detail) + ", " + std::to_string(left_s) +
                             " s left";
  if (terminal_) {
    constexpr int kBarChars = 30;
    const int filled = kBarChars * std::clamp(done, 0, total_) / total_;
    // Carriage return, the bar, and clear to the end of the line (a shorter status than the last).
    err_ << "\r[" << std::string(filled, '#') << std::string(kBarChars - filled, '.') << "] "
         << status << "\033[K" << std::flush;
    bar_drawn_ = true;
  } else if (done >= total_ || last_line_done_ < 0 || done - last_line_done_ >= total_ / 100 ||
             elapsed_s - last_line_s_ >= 10) {
    err_ << status << "\n" << std::flush;
    last_line_done_ = done;
    last_line_s_ = elapsed_s;
  }
}

void Progress::finish() {
  if (bar_drawn_) err_ << "\n" << std::flush;
  bar_drawn_ = false;
}

}  // namespace fr
