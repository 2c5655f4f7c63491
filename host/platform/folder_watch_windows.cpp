#include "platform/folder_watch.hpp"

#include <windows.h>

namespace fr {

struct FolderWatch::State {
  HANDLE change = INVALID_HANDLE_VALUE;
};

FolderWatch::FolderWatch(const std::filesystem::path& folder) : state_(std::make_unique<State>()) {
  // A change notification handle is signalled when a name, size or write time in the folder
  // changes; re-armed after each look.
  state_->change = FindFirstChangeNotificationW(
      folder.c_str(), FALSE,
      FILE_NOTIFY_CHANGE_FILE_NAME | FILE_NOTIFY_CHANGE_SIZE | FILE_NOTIFY_CHANGE_LAST_WRITE);
}

FolderWatch::~FolderWatch() {
  if (state_->change != INVALID_HANDLE_VALUE) FindCloseChangeNotification(state_->change);
}

bool FolderWatch::active() const {
  return state_->change != INVALID_HANDLE_VALUE;
}

bool FolderWatch::changed() {
  if (state_->change == INVALID_HANDLE_VALUE) return false;
  if (WaitForSingleObject(state_->change, 0) != WAIT_OBJECT_0) return false;
  if (!FindNextChangeNotification(state_->change)) {
    FindCloseChangeNotification(state_->change);
    state_->change = INVALID_HANDLE_VALUE;  // the caller polls from now on
  }
  return true;
}

}  // namespace fr
