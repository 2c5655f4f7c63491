#include "platform/folder_watch.hpp"

#include <sys/inotify.h>
#include <unistd.h>

#include <array>

namespace fr {

struct FolderWatch::State {
  int fd = -1;
};

FolderWatch::FolderWatch(const std::filesystem::path& folder) : state_(std::make_unique<State>()) {
  state_->fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (state_->fd >= 0 && inotify_add_watch(state_->fd, folder.c_str(),
                                           IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM |
                                               IN_DELETE | IN_CREATE | IN_MODIFY) < 0) {
    close(state_->fd);
    state_->fd = -1;
  }
}

FolderWatch::~FolderWatch() {
  if (state_->fd >= 0) close(state_->fd);
}

bool FolderWatch::active() const {
  return state_->fd >= 0;
}

bool FolderWatch::changed() {
  if (state_->fd < 0) return false;
  std::array<char, 4096> buffer;
  bool events = false;
  while (read(state_->fd, buffer.data(), buffer.size()) > 0) events = true;
  return events;
}

}  // namespace fr
