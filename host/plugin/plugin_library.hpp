// plugin_library.hpp — one loaded scene plugin: its file read once, loaded from a private copy
// of those bytes (platform/shared_library.hpp says how, and why), and unloaded after the
// plugin's deinit.
//
// Loading runs the library's constructors in the calling process. The host does this only in a
// scene-host process (scene_host_process.hpp) unless plugins.isolation = "none".
#pragma once

#include "platform/files.hpp"
#include "platform/shared_library.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace fr {

class PluginLibrary {
 public:
  // Reads the plugin `opened` (see open_plugin_file), checks that it is a complete library for
  // this host (check_library_bytes) and loads a private copy. On failure returns null and sets
  // *error to a sentence naming what went wrong; messages name `file`, never the private copy.
  static std::shared_ptr<PluginLibrary> open(const ReadableFile& opened,
                                             const std::filesystem::path& file, std::string* error);

  ~PluginLibrary();
  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;

  // The address of an exported symbol, or null.
  const void* symbol(const char* name) const;

  // The plugin's deinit (ABI 1.1), called just before the library is closed.
  void set_deinit(void (*deinit)(void)) { deinit_ = deinit; }

 private:
  explicit PluginLibrary(std::unique_ptr<SharedLibrary> library) : library_(std::move(library)) {}
  std::unique_ptr<SharedLibrary> library_;
  void (*deinit_)(void) = nullptr;
};

}  // namespace fr
