#include "io/cache_dirs.hpp"

#include <cstdlib>

namespace fr {

std::filesystem::path fractalis_cache_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "fractalis";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "fractalis";
  return {};
}

const std::vector<CacheFolder>& cache_folders() {
  static const std::vector<CacheFolder> folders = {
      {"kernels", "compiled OpenCL kernels (PoCL's cache), bounded by cache.kernel_cache_mib"},
      {"scenes", "which plugin files loaded, by file identity"},
      {"vetted", "which scene files passed the explorer's test render"},
      {"sweep", "reference images of fractalis sweep"},
  };
  return folders;
}

}  // namespace fr
