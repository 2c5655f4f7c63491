// folder_watch.hpp — being told that something in a folder changed, without scanning it.
//
// Says only "look": which file changed, and whether it is finished, the caller finds out by
// scanning (plugin/plugin_watcher.hpp). Where the system cannot watch the folder (too many
// watches, a network share) active() is false and the caller polls.
#pragma once

#include <filesystem>
#include <memory>

namespace fr {

class FolderWatch {
 public:
  explicit FolderWatch(const std::filesystem::path& folder);
  ~FolderWatch();
  FolderWatch(const FolderWatch&) = delete;
  FolderWatch& operator=(const FolderWatch&) = delete;

  bool active() const;
  // Whether anything in the folder was created, written, renamed or removed since the last call
  // (or since the watch began). Never blocks; false when not active.
  bool changed();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace fr
