#include "plugin/scan_cache.hpp"

#include "io/cache_dirs.hpp"

#include "io/atomic_file.hpp"
#include "plugin/scene_wire.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace fr {
namespace {

constexpr size_t kMaxKeptScans = 256;

std::filesystem::path entry_path(const FileIdentity& id) {
  // The answer depends on the host's build too (its ABI minor and its checks), not only on the
  // file: an upgraded fractalis scans again.
  char name[200];
  std::snprintf(
      name, sizeof name, "%llx-%llx-%llx-%llx-%llx-w%u-abi%u.%u-%s.scan",
      static_cast<unsigned long long>(id.device), static_cast<unsigned long long>(id.inode),
      static_cast<unsigned long long>(id.size_bytes), static_cast<unsigned long long>(id.mtime_ns),
      static_cast<unsigned long long>(id.ctime_ns), kSceneWireVersion, FR_ABI_VERSION_MAJOR,
      FR_ABI_VERSION_MINOR, FRACTALIS_VERSION);
  return scan_cache_dir() / name;
}

}  // namespace

std::filesystem::path scan_cache_dir() {
  const auto base = fractalis_cache_dir();
  return base.empty() ? base : base / "scenes";
}

std::optional<std::string> find_scan(const FileIdentity& identity) {
  if (scan_cache_dir().empty()) return std::nullopt;
  const int fd = open(entry_path(identity).c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  std::optional<std::string> bytes;
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_uid == geteuid() &&
      st.st_size <= static_cast<off_t>(kMaxFrameBytes)) {
    std::string b(static_cast<size_t>(st.st_size), '\0');
    if (pread(fd, b.data(), b.size(), 0) == static_cast<ssize_t>(b.size())) bytes = std::move(b);
  }
  close(fd);
  return bytes;
}

void keep_scan(const FileIdentity& identity, const std::string& loaded_message) {
  const auto dir = scan_cache_dir();
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return;
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all, ec);
  // Bounded: past the cap, the oldest entries go (plugins that were rebuilt since).
  std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> entries;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".scan") entries.emplace_back(e.last_write_time(ec), e.path());
  if (entries.size() >= kMaxKeptScans) {
    std::sort(entries.begin(), entries.end());
    for (size_t i = 0; i + kMaxKeptScans / 2 < entries.size(); ++i)
      std::filesystem::remove(entries[i].second, ec);
  }
  std::string error;
  write_file_atomic(entry_path(identity), loaded_message, &error);
}

}  // namespace fr
