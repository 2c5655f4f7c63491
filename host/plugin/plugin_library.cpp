#include "plugin/plugin_library.hpp"

namespace fr {
namespace {

// Far above any scene plugin (the in-tree ones are tens of KB); reading more would only hold a
// hostile file in memory.
constexpr uint64_t kMaxPluginBytes = uint64_t{1} << 30;

}  // namespace

std::shared_ptr<PluginLibrary> PluginLibrary::open(const ReadableFile& opened,
                                                   const std::filesystem::path& file,
                                                   std::string* error) {
  if (opened.kind() != PathKind::Regular) {
    *error = "not a regular file";
    return nullptr;
  }
  if (opened.identity().size_bytes > kMaxPluginBytes) {
    *error = "larger than 1 GiB: not a scene plugin";
    return nullptr;
  }
  // Read once: the bytes checked are the bytes loaded, whatever happens to the file meanwhile.
  std::string bytes;
  if (!opened.read_all(opened.identity().size_bytes + (1 << 20), &bytes, error)) {
    if (error->rfind("more than", 0) == 0) *error = "the file grew while it was being read";
    return nullptr;
  }
  std::unique_ptr<SharedLibrary> library = SharedLibrary::load_private_copy(bytes, file, error);
  if (!library) return nullptr;
  return std::shared_ptr<PluginLibrary>(new PluginLibrary(std::move(library)));
}

PluginLibrary::~PluginLibrary() {
  if (deinit_) {
    try {
      deinit_();
    } catch (...) {
      // Nothing to recover: the library goes either way.
    }
  }
}

const void* PluginLibrary::symbol(const char* name) const {
  return library_->symbol(name);
}

}  // namespace fr
