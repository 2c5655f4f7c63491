// plugin_library.hpp — one dlopen'ed scene plugin, loaded from a private copy of its file.
//
// Loading from a copy means the file in the plugin folder can be replaced (a rebuild, a hot
// reload) while this one stays mapped. The copy is unlinked as soon as it is mapped, so nothing
// is left in the temporary folder even if the host crashes.
#pragma once

#include <filesystem>
#include <string>

namespace fr {

class PluginLibrary {
 public:
  // Copies `file` privately and dlopens the copy. On failure returns null and sets *error to a
  // sentence naming what went wrong (not an ELF file, truncated, unresolved symbol, ...).
  static std::shared_ptr<PluginLibrary> open(const std::filesystem::path& file, std::string* error);

  ~PluginLibrary();
  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;

  // The address of an exported symbol, or null.
  const void* symbol(const char* name) const;

 private:
  explicit PluginLibrary(void* handle) : handle_(handle) {}
  void* handle_;
};

}  // namespace fr
