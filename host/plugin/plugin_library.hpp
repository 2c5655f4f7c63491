// plugin_library.hpp — one dlopen'ed scene plugin, loaded from a private in-memory copy.
//
// The copy is a memfd: it has no name in any folder, so no other user can plant or swap a file
// on the way to dlopen, nothing is left behind however the process ends, and the file in the
// plugin folder can be replaced (a rebuild, a hot reload) while this one stays mapped.
//
// Loading runs the library's constructors in the calling process. The host does this only in a
// scene-host process (scene_host_process.hpp) unless plugins.isolation = "none".
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace fr {

class PluginLibrary {
 public:
  // Copies the plugin read from `fd` (see open_plugin_file; not closed here) into a memfd, checks
  // that it is a complete ELF shared library for this host's architecture, and dlopens it. On
  // failure returns null and sets *error to a sentence naming what went wrong; messages name
  // `file`, never the private copy.
  static std::shared_ptr<PluginLibrary> open(int fd, const std::filesystem::path& file,
                                             std::string* error);

  ~PluginLibrary();
  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;

  // The address of an exported symbol, or null.
  const void* symbol(const char* name) const;

  // The plugin's deinit (ABI 1.1), called just before the library is closed.
  void set_deinit(void (*deinit)(void)) { deinit_ = deinit; }

 private:
  PluginLibrary(void* handle, int memfd) : handle_(handle), memfd_(memfd) {}
  void* handle_;
  int memfd_;  // kept open while mapped: its /proc/self/fd name must not be reused meanwhile
  void (*deinit_)(void) = nullptr;
};

// "" when `bytes` starts a complete ELF shared library of this process's own class, byte order
// and machine; otherwise why not ("built for AArch64, this host is x86-64", "truncated: ...").
// `read_at(offset, buffer, size)` returns the bytes read.
std::string check_elf_library(uint64_t size_bytes,
                              const std::function<size_t(uint64_t, void*, size_t)>& read_at);

}  // namespace fr
