// plugin_files.hpp — finding plugin files in a folder and opening them, safely.
//
// A plugin folder is a place where other programs drop files, so nothing in it is trusted: a
// `*.so` (`*.dll` on Windows) may be a FIFO (opening it for reading would block forever), a device,
// a socket, a directory, a dangling symlink or a symlink loop. Each such entry is skipped with its
// reason and nothing in a scan ever blocks. Folders and files that users other than the owner could
// write to are refused (another user could swap the code the host runs), unless the settings allow
// it.
#pragma once

#include "platform/files.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fr {

struct PluginFile {
  std::filesystem::path path;  // as found in the folder (the name the user knows)
  std::string skip_reason;     // empty: a regular file worth loading
};

// Every entry named `*.so` (`*.dll`) in `folder`, sorted by name, each either loadable or with the
// reason it is skipped. When the folder itself is refused (writable by others, missing) the result
// is one entry for the folder with the reason.
std::vector<PluginFile> list_plugin_files(const std::filesystem::path& folder, bool allow_writable);

// Why `folder` (or one of its parents) could be changed by another user, or "" when it cannot.
std::string writable_by_others(const std::filesystem::path& folder);

// Opens a plugin file for reading without blocking, and only a regular file: returns it (its
// identity() tells a rebuilt file), or an invalid ReadableFile and *error ("a FIFO, not a shared
// library", "a symlink loop", "the file is writable by every user ...", ...).
ReadableFile open_plugin_file(const std::filesystem::path& file, bool allow_writable,
                              std::string* error);

// The largest plugin file the host reads (a scene is kilobytes; this bounds memory and time).
constexpr uint64_t kMaxPluginFileBytes = uint64_t{256} << 20;

}  // namespace fr
