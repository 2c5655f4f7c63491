#include "io/log.hpp"

#include <spdlog/sinks/base_sink.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <deque>
#include <memory>
#include <mutex>

namespace fr {
namespace {

// "warning: " for warnings and up, "" for info, "debug: " below: how a line starts.
std::string level_prefix(spdlog::level::level_enum level) {
  switch (level) {
    case spdlog::level::critical:
    case spdlog::level::err:
      return "error: ";
    case spdlog::level::warn:
      return "warning: ";
    case spdlog::level::info:
      return "";
    default:
      return "debug: ";
  }
}

// The command's error stream: one "fractalis: ..." line per message, flushed at once.
class StreamSink : public spdlog::sinks::base_sink<std::mutex> {
 public:
  explicit StreamSink(std::ostream& out) : out_(out) {}

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {
    out_ << "fractalis: " << level_prefix(msg.level)
         << std::string_view(msg.payload.data(), msg.payload.size()) << "\n";
    out_.flush();
  }
  void flush_() override { out_.flush(); }

 private:
  std::ostream& out_;
};

// The overlay's list: the last kKept lines.
class HistorySink : public spdlog::sinks::base_sink<std::mutex> {
 public:
  std::vector<std::string> last(size_t count) {
    std::lock_guard<std::mutex> lock(mutex_);
    const size_t n = std::min(count, lines_.size());
    return {lines_.end() - static_cast<std::ptrdiff_t>(n), lines_.end()};
  }

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {
    lines_.push_back(level_prefix(msg.level) + std::string(msg.payload.data(), msg.payload.size()));
    while (lines_.size() > kKept) lines_.pop_front();
  }
  void flush_() override {}

 private:
  static constexpr size_t kKept = 64;
  std::deque<std::string> lines_;
};

std::mutex g_history_mutex;
std::shared_ptr<HistorySink> g_history;
LogVerbosity g_verbosity = LogVerbosity::Normal;

}  // namespace

LogSession::LogSession(std::ostream& err, const LogOptions& options) {
  auto stream = std::make_shared<StreamSink>(err);
  stream->set_level(options.verbosity == LogVerbosity::Quiet     ? spdlog::level::err
                    : options.verbosity == LogVerbosity::Verbose ? spdlog::level::debug
                                                                 : spdlog::level::info);
  auto history = std::make_shared<HistorySink>();
  history->set_level(spdlog::level::info);
  std::vector<spdlog::sink_ptr> sinks = {stream, history};
  if (!options.file.empty()) {
    try {
      auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>(options.file.string());
      file->set_level(spdlog::level::debug);
      file->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [%l] %v");
      sinks.push_back(file);
    } catch (const spdlog::spdlog_ex& e) {
      throw std::runtime_error("--log-file: cannot write '" + options.file.string() +
                               "': " + e.what());
    }
  }
  auto logger = std::make_shared<spdlog::logger>("fractalis", sinks.begin(), sinks.end());
  logger->set_level(spdlog::level::debug);
  logger->flush_on(spdlog::level::debug);
  spdlog::set_default_logger(logger);
  std::lock_guard<std::mutex> lock(g_history_mutex);
  g_history = history;
  g_verbosity = options.verbosity;
}

LogSession::~LogSession() {
  {
    std::lock_guard<std::mutex> lock(g_history_mutex);
    g_history.reset();
    g_verbosity = LogVerbosity::Normal;
  }
  // Plain stderr again: the error stream given may be gone after this.
  spdlog::set_default_logger(std::make_shared<spdlog::logger>(
      "fractalis", std::make_shared<spdlog::sinks::stderr_color_sink_mt>()));
}

LogVerbosity log_verbosity() {
  std::lock_guard<std::mutex> lock(g_history_mutex);
  return g_verbosity;
}

std::vector<std::string> recent_log_messages(size_t count) {
  std::lock_guard<std::mutex> lock(g_history_mutex);
  return g_history ? g_history->last(count) : std::vector<std::string>{};
}

}  // namespace fr
