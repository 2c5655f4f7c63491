// kernel_cache.hpp — the compiled-kernel cache: where it is, and keeping it bounded.
//
// PoCL compiles each program (and each work-group shape of each kernel) with LLVM and keeps the
// result in its kernel cache, which makes a second start of a scene fast. Left alone it lives in
// ~/.cache/pocl, grows without bound and collects empty "tempfile_*" files from builds that were
// interrupted. fractalis points PoCL at $XDG_CACHE_HOME/fractalis/kernels instead (unless the
// user set POCL_CACHE_DIR), and before each command's OpenCL work trims it: empty temporary files
// older than ten minutes go, then whole programs, least recently used first (PoCL touches each
// program's last_accessed file when it uses it), until the cache is within
// cache.kernel_cache_mib.
#pragma once

#include <cstdint>
#include <filesystem>

namespace fr {

// The folder PoCL caches compiled kernels in: $POCL_CACHE_DIR when set, else
// <fractalis_cache_dir()>/kernels.
std::filesystem::path kernel_cache_dir();

// True when the kernel cache is fractalis's own folder: a POCL_CACHE_DIR the user set elsewhere
// is theirs, and fractalis neither trims nor clears it.
bool kernel_cache_is_ours();

// Sets POCL_CACHE_DIR to kernel_cache_dir() unless the user set it. Call before any OpenCL call
// (the platform reads it once, when it starts).
void use_kernel_cache_dir();

struct KernelCacheTrim {
  uint64_t bytes_before = 0;
  uint64_t bytes_after = 0;
  int programs_removed = 0;
  int temp_files_removed = 0;
};

// Trims `dir` (laid out as PoCL's cache with POCL_CACHE_DIR: <dir>/XX/<program>/..., and
// <dir>/tempfile_*) to at most `max_bytes`.
KernelCacheTrim trim_kernel_cache(const std::filesystem::path& dir, uint64_t max_bytes);

// Bytes of the regular files under `dir` (0 when it does not exist).
uint64_t folder_bytes(const std::filesystem::path& dir);

}  // namespace fr
