// scan_cache.hpp — what scanning a plugin file found, kept by the file's identity.
//
// Listing a folder loads each plugin in a scene-host process; a plugin that has not changed since
// (same device, inode, size, modification and change times) gives the same answer, so the
// answer is kept in $XDG_CACHE_HOME/fractalis/scenes/ and `fractalis list` or a start of the
// explorer runs no plugin code for it. What is read back is checked exactly like a fresh answer.
// Only answers that depend on the file alone are kept: a crash, a time-out or a library the
// system could not load (it may lack a library the plugin needs, until that is installed) is
// tried again.
#pragma once

#include "plugin/plugin_files.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace fr {

// The cache folder ($XDG_CACHE_HOME/fractalis/scenes or ~/.cache/fractalis/scenes); empty when
// neither is set, which turns the cache off.
std::filesystem::path scan_cache_dir();

// The Loaded message a scene host sent for a file with this identity, if kept.
std::optional<std::string> find_scan(const FileIdentity& identity);

// Keeps a Loaded message (atomically, readable by the user only). Failures are ignored: the
// cache only saves time.
void keep_scan(const FileIdentity& identity, const std::string& loaded_message);

}  // namespace fr
