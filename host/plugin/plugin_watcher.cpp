#include "plugin/plugin_watcher.hpp"

#include "platform/shared_library.hpp"

namespace fr {

PluginWatcher::PluginWatcher(std::filesystem::path folder, double debounce_s,
                             double poll_interval_s)
    : folder_(std::move(folder)),
      debounce_s_(debounce_s),
      poll_interval_s_(poll_interval_s),
      watch_(folder_) {
  reported_ = scan();
}

PluginWatcher::~PluginWatcher() = default;

std::map<std::filesystem::path, PluginWatcher::Stamp> PluginWatcher::scan() const {
  std::map<std::filesystem::path, Stamp> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder_, ec)) {
    if (!is_library_file_name(e.path()) || !e.is_regular_file(ec)) continue;
    std::string error;  // (a file that went away between the listing and this: not there)
    if (const auto id = identity_of(e.path(), &error)) out[e.path()] = *id;
  }
  return out;
}

std::vector<PluginChange> PluginWatcher::poll(double now_s) {
  bool look = !pending_.empty() || now_s - last_scan_s_ >= poll_interval_s_;
  if (watch_.active()) {
    // Watched, scan on events, while something is settling, and rarely as a safety net.
    look = watch_.changed() || !pending_.empty() || now_s - last_scan_s_ >= 10 * poll_interval_s_;
  }
  std::vector<PluginChange> changes;
  if (!look) return changes;
  last_scan_s_ = now_s;
  const auto current = scan();
  for (const auto& [file, stamp] : current) {
    auto known = reported_.find(file);
    if (known != reported_.end() && known->second == stamp) {
      pending_.erase(file);
      continue;
    }
    auto& p = pending_[file];
    if (!p.started || !(p.stamp == stamp)) {
      p.stamp = stamp;
      p.stable_since_s = now_s;
      p.started = true;
      continue;
    }
    if (now_s - p.stable_since_s >= debounce_s_) {
      changes.push_back(
          {known == reported_.end() ? PluginChange::Kind::Added : PluginChange::Kind::Modified,
           file});
      reported_[file] = stamp;
      pending_.erase(file);
    }
  }
  for (auto it = reported_.begin(); it != reported_.end();) {
    if (current.count(it->first)) {
      ++it;
      continue;
    }
    changes.push_back({PluginChange::Kind::Removed, it->first});
    pending_.erase(it->first);
    it = reported_.erase(it);
  }
  for (auto it = pending_.begin(); it != pending_.end();)
    it = current.count(it->first) ? std::next(it) : pending_.erase(it);
  return changes;
}

}  // namespace fr
