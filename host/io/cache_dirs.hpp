// cache_dirs.hpp — where fractalis keeps what it can rebuild: one folder, $XDG_CACHE_HOME/fractalis
// (~/.cache/fractalis when XDG_CACHE_HOME is unset), with one subfolder per cache. `fractalis
// cache` lists them with their sizes and `fractalis cache --clear` empties them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fr {

// $XDG_CACHE_HOME/fractalis or ~/.cache/fractalis; empty when neither variable is set.
std::filesystem::path fractalis_cache_dir();

struct CacheFolder {
  const char* name;         // the subfolder
  const char* description;  // what it holds
};
// kernels: compiled OpenCL programs (render/kernel_cache.hpp); scenes: plugin scan verdicts
// (plugin/scan_cache.hpp); vetted: test-render markers (render/scene_vetting.hpp); sweep: reference
// images of `fractalis sweep`; thumbnails: the scene browser's pictures (app/thumbnail_cache.hpp).
const std::vector<CacheFolder>& cache_folders();

}  // namespace fr
