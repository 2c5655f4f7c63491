// shared_library.hpp — a dynamic library (a scene plugin) loaded from a private copy of its bytes.
//
// The caller reads the plugin's file once; what is checked is what is loaded. The copy has no
// name another user could plant or swap a file under on the way to the loader, and the file in
// the plugin folder can be replaced (a rebuild, a hot reload) while the copy stays loaded.
// Linux: a sealed memfd, loaded through /proc/self/fd/N; nothing is left behind however the
// process ends. Windows: a file of a new, unguessable name in the user's own fractalis folder
// (%LOCALAPPDATA%\fractalis\plugin-copies), kept open without write or delete sharing until it is
// loaded, and removed when it is unloaded; copies that a process which ended abruptly left there
// are removed by a later load once they are a minute old (a loaded one cannot be).
//
// Loading runs the library's initialisers in the calling process: fractalis does this only in a
// scene-host process (plugin/scene_host_process.hpp) unless plugins.isolation = "none".
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace fr {

class SharedLibrary {
 public:
  // Checks `bytes` (check_library_bytes), copies them privately and loads the copy. Null with
  // *error when it cannot; messages name `named_as`, never the copy.
  static std::unique_ptr<SharedLibrary> load_private_copy(const std::string& bytes,
                                                          const std::filesystem::path& named_as,
                                                          std::string* error);
  ~SharedLibrary();  // unloads it
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The address of an exported symbol, or null.
  const void* symbol(const char* name) const;

 private:
  SharedLibrary() = default;
  void* handle_ = nullptr;               // dlopen's, or the HMODULE
  [[maybe_unused]] intptr_t copy_ = -1;  // Linux: the memfd, kept open while loaded
  std::filesystem::path copy_path_;      // Windows: the copy, removed once unloaded
};

// "" when `bytes` are a complete dynamic library of this process's own kind — on Linux an ELF
// shared object of its class, byte order and machine; on Windows a PE DLL for its machine — with
// every header and section inside the bytes (a loader maps a truncated library and then faults
// on the missing pages); otherwise why not ("built for AArch64, this host is x86-64",
// "truncated: ...").
std::string check_library_bytes(const std::string& bytes);

// How many mappings of private copies this process holds (Linux: ranges of the memfds in
// /proc/self/maps; Windows: modules loaded from the copies' folder). After every library was
// unloaded, more than none means something pins one (a thread, a TLS destructor).
size_t private_copy_mappings();

// The file name of library `name` on this system: `name`.so on Linux, `name`.dll on Windows.
std::string library_file_name(const std::string& name);

// Whether a file's name says it is a library on this system: `*.so` on Linux; `*.dll`, in any
// case (the system ignores it), on Windows.
bool is_library_file_name(const std::filesystem::path& file);

}  // namespace fr
