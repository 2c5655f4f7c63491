#include "plugin/plugin_library.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace fr {
namespace {

// Far above any scene plugin (the in-tree ones are tens of KB); reading more would only hold a
// hostile file in memory.
constexpr uint64_t kMaxPluginBytes = uint64_t{1} << 30;

}  // namespace

std::shared_ptr<PluginLibrary> PluginLibrary::open(int fd, const std::filesystem::path& file,
                                                   std::string* error) {
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    *error = "not a regular file";
    return nullptr;
  }
  if (static_cast<uint64_t>(st.st_size) > kMaxPluginBytes) {
    *error = "larger than 1 GiB: not a scene plugin";
    return nullptr;
  }
  // Read once: the bytes checked are the bytes loaded, whatever happens to the file meanwhile.
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = pread(fd, buffer, sizeof buffer, static_cast<off_t>(bytes.size()));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      *error = std::string("cannot read: ") + std::strerror(errno);
      return nullptr;
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<size_t>(n));
    if (bytes.size() > static_cast<uint64_t>(st.st_size) + (1 << 20)) {
      *error = "the file grew while it was being read";
      return nullptr;
    }
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
