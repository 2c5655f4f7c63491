#include "render/kernel_cache.hpp"

#include "io/cache_dirs.hpp"
#include "platform/user_folders.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace fr {
namespace {

namespace fs = std::filesystem;

struct Program {
  fs::path dir;
  time_t used_s = 0;  // last_accessed's mtime, else the folder's
  uint64_t bytes = 0;
};

// Seconds since the epoch (time()'s clock) of p's last change; 0 when it cannot be read.
time_t mtime_s(const fs::path& p) {
  std::error_code ec;
  const fs::file_time_type t = fs::last_write_time(p, ec);
  if (ec) return 0;
  const auto age =
      std::chrono::duration_cast<std::chrono::seconds>(fs::file_time_type::clock::now() - t);
  return std::time(nullptr) - static_cast<time_t>(age.count());
}

}  // namespace

fs::path kernel_cache_dir() {
  if (const char* pocl = std::getenv("POCL_CACHE_DIR"); pocl && *pocl) return pocl;
  const auto base = fractalis_cache_dir();
  return base.empty() ? base : base / "kernels";
}

bool kernel_cache_is_ours() {
  const auto base = fractalis_cache_dir();
  return !base.empty() && kernel_cache_dir() == base / "kernels";
}

void use_kernel_cache_dir() {
  if (const char* pocl = std::getenv("POCL_CACHE_DIR"); pocl && *pocl) return;
  const auto dir = kernel_cache_dir();
  if (dir.empty()) return;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!ec) set_environment_variable("POCL_CACHE_DIR", dir);
}

uint64_t folder_bytes(const fs::path& dir) {
  uint64_t total = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec),
       end;
       !ec && it != end; it.increment(ec)) {
    std::error_code size_ec;
    if (it->is_regular_file(size_ec)) {
      const auto size = it->file_size(size_ec);
      if (!size_ec) total += size;
    }
  }
  return total;
}

KernelCacheTrim trim_kernel_cache(const fs::path& dir, uint64_t max_bytes) {
  KernelCacheTrim trim;
  const fs::path& kcache = dir;
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(kcache, ec)) return trim;
  const time_t now = std::time(nullptr);
  std::vector<Program> programs;
  uint64_t total = 0;
  for (fs::directory_iterator bucket(kcache, ec), end; !ec && bucket != end; bucket.increment(ec)) {
    std::error_code entry_ec;
    if (!bucket->is_directory(entry_ec)) {
      // A temporary file a build left when its process was ended (a render worker over its build
      // limit leaves its preprocessed source, up to the worker's file size limit): an older one,
      // since a build may be running. Younger ones are not counted: removing programs cannot
      // make room for them.
      const std::string name = bucket->path().filename().string();
      if (name.rfind("tempfile_", 0) == 0) {
        if (now - mtime_s(bucket->path()) > 600 && fs::remove(bucket->path(), entry_ec))
          ++trim.temp_files_removed;
      } else {
        total += entry_ec ? 0 : bucket->file_size(entry_ec);
      }
      continue;
    }
    for (fs::directory_iterator prog(bucket->path(), entry_ec), pend; !entry_ec && prog != pend;
         prog.increment(entry_ec)) {
      Program p;
      p.dir = prog->path();
      const time_t accessed = mtime_s(p.dir / "last_accessed");
      p.used_s = accessed ? accessed : mtime_s(p.dir);
      p.bytes = folder_bytes(p.dir);
      total += p.bytes;
      programs.push_back(std::move(p));
    }
  }
  trim.bytes_before = total;
  std::sort(programs.begin(), programs.end(),
            [](const Program& a, const Program& b) { return a.used_s < b.used_s; });
  for (const Program& p : programs) {
    if (total <= max_bytes) break;
    // Used in the last two minutes: another process may be building or loading it right now.
    if (now - p.used_s < 120) continue;
    std::error_code remove_ec;
    fs::remove_all(p.dir, remove_ec);
    if (remove_ec) continue;
    total -= p.bytes;
    ++trim.programs_removed;
  }
  trim.bytes_after = total;
  return trim;
}

}  // namespace fr
