// plugin_watcher.hpp — noticing scene plugins that appear in, change in or leave a folder.
//
// The system's folder watch (platform/folder_watch.hpp: inotify, Windows' change notifications)
// says when to look (without it, the folder is polled every poll_interval_s); a file is
// reported only once its size and modification time have stayed the same for debounce_s, so a
// plugin that is still being copied or linked is never loaded half-written.
#pragma once

#include "platform/files.hpp"

#include "platform/folder_watch.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

namespace fr {

struct PluginChange {
  enum class Kind { Added, Modified, Removed };
  Kind kind;
  std::filesystem::path file;
};

class PluginWatcher {
 public:
  explicit PluginWatcher(std::filesystem::path folder, double debounce_s = 0.3,
                         double poll_interval_s = 0.5);
  ~PluginWatcher();
  PluginWatcher(const PluginWatcher&) = delete;
  PluginWatcher& operator=(const PluginWatcher&) = delete;

  // The changes that became stable by `now_s` (a monotonic clock, seconds). Files present when
  // the watcher starts count as known, not added. Cheap when nothing happened.
  std::vector<PluginChange> poll(double now_s);

  bool watched() const { return watch_.active(); }
  const std::filesystem::path& folder() const { return folder_; }

 private:
  // What tells a rebuilt file from the one before (platform/files.hpp).
  using Stamp = FileIdentity;
  struct Pending {
    Stamp stamp;
    double stable_since_s = 0;
    bool started = false;
  };
  std::map<std::filesystem::path, Stamp> scan() const;

  std::filesystem::path folder_;
  double debounce_s_, poll_interval_s_;
  FolderWatch watch_;
  double last_scan_s_ = -1e300;
  std::map<std::filesystem::path, Stamp> reported_;   // what the caller knows
  std::map<std::filesystem::path, Pending> pending_;  // changed, waiting to be stable
};

}  // namespace fr
