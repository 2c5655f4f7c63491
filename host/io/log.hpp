// log.hpp — the one channel for errors, warnings and events: spdlog's default logger, set up
// once per command by a LogSession. Everything the CLI, the explorer, the plugin loader and the
// plugins themselves report goes through it (spdlog::error / warn / info / debug), and from there
// to up to three sinks:
//   - the command's error stream (stderr), as "fractalis: warning: ..." lines, filtered by the
//     verbosity (-q: errors only; default: info and up; -v: debug too);
//   - the log file, when --log-file names one: every message from debug up, time-stamped;
//   - the recent-messages list the explorer's overlay shows (info and up), so the window and
//     the terminal say the same things.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace fr {

enum class LogVerbosity { Quiet, Normal, Verbose };

struct LogOptions {
  LogVerbosity verbosity = LogVerbosity::Normal;
  std::filesystem::path file;  // empty: no log file
};

// Installs the channel for the lifetime of the object and restores spdlog's plain default logger
// after it (so a test's error stream is never written once it is gone). Throws
// std::runtime_error naming the file when the log file cannot be opened.
class LogSession {
 public:
  LogSession(std::ostream& err, const LogOptions& options);
  ~LogSession();
  LogSession(const LogSession&) = delete;
  LogSession& operator=(const LogSession&) = delete;
};

// The verbosity of the session installed now (Normal when none is).
LogVerbosity log_verbosity();

// The newest messages at info level and above (at most `count`, oldest first), as
// "warning: ..." lines; empty when no session is installed.
std::vector<std::string> recent_log_messages(size_t count);

}  // namespace fr
