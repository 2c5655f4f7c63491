#include "plugin/scan_cache.hpp"

#include "io/cache_dirs.hpp"

#include "io/atomic_file.hpp"
#include "plugin/scene_wire.hpp"

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
  // Only a regular file that nobody else could have written (the folder is this user's own).
  std::string error;
  const ReadableFile entry = ReadableFile::open(entry_path(identity), &error);
  std::string bytes;
  if (!entry.valid() || entry.kind() != PathKind::Regular ||
      !entry.others_who_can_write().empty() || !entry.read_all(kMaxFrameBytes, &bytes, &error))
    return std::nullopt;
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
