// plugin_files.hpp — finding plugin files in a folder and opening them, safely.
//
// A plugin folder is a place where other programs drop files, so nothing in it is trusted: a
// `*.so` may be a FIFO (opening it for reading would block forever), a device, a socket, a
// directory, a dangling symlink or a symlink loop. Each such entry is skipped with its reason and
// nothing in a scan ever blocks. Folders and files that users other than the owner could write
// to are refused (another user could swap the code the host runs), unless the settings allow it.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace fr {

struct PluginFile {
  std::filesystem::path path;  // as found in the folder (the name the user knows)
  std::string skip_reason;     // empty: a regular file worth loading
};

// Every entry named `*.so` in `folder`, sorted by name, each either loadable or with the reason
// it is skipped. When the folder itself is refused (writable by others, missing) the result is
// one entry for the folder with the reason.
std::vector<PluginFile> list_plugin_files(const std::filesystem::path& folder, bool allow_writable);

// Why `folder` (or one of its parents) could be changed by another user, or "" when it cannot.
std::string writable_by_others(const std::filesystem::path& folder);

// The identity of a file's contents as the file system sees it: device, inode, size, and the
// modification and change times in nanoseconds. A rebuilt plugin differs in at least one.
struct FileIdentity {
  dev_t device = 0;
  ino_t inode = 0;
  off_t size_bytes = 0;
  int64_t mtime_ns = 0;
  int64_t ctime_ns = 0;
  bool operator==(const FileIdentity&) const = default;
};

// Opens a plugin file for reading without blocking and without following it into anything but a
// regular file: returns a close-on-exec descriptor, or -1 and sets *error ("a FIFO", "a symlink
// loop", "writable by other users", ...). `identity` receives the file's identity when not null.
int open_plugin_file(const std::filesystem::path& file, bool allow_writable, std::string* error,
                     FileIdentity* identity = nullptr);

// The largest plugin file the host reads (a scene is kilobytes; this bounds memory and time).
constexpr off_t kMaxPluginFileBytes = off_t{256} << 20;

}  // namespace fr
