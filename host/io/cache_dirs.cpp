#include "io/cache_dirs.hpp"

#include "platform/user_folders.hpp"

namespace fr {

std::filesystem::path fractalis_cache_dir() {
  return user_folder(UserFolder::Cache);
}

const std::vector<CacheFolder>& cache_folders() {
  static const std::vector<CacheFolder> folders = {
      {"kernels", "compiled OpenCL kernels (PoCL's cache), bounded by cache.kernel_cache_mib"},
      {"scenes", "which plugin files loaded, by file identity"},
      {"vetted", "which scene files passed the explorer's test render"},
      {"sweep", "reference images of fractalis sweep"},
      {"thumbnails", "the explorer's scene browser pictures"},
  };
  return folders;
}

}  // namespace fr
