#include "platform/system_facts.hpp"

#include <malloc.h>
#include <sys/resource.h>
#include <sys/utsname.h>

#if defined(__SANITIZE_ADDRESS__)
// From the sanitizer runtime (sanitizer/allocator_interface.h, which Debian's GCC does not ship).
extern "C" size_t __sanitizer_get_current_allocated_bytes(void);
#endif

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fr {
namespace {

// The value after "key" and a separator (':' or '=') on the first line that starts with it.
std::string read_field(const char* file, const std::string& key, char separator) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    auto pos = line.find(separator);
    if (pos == std::string::npos) continue;
    std::string value = line.substr(pos + 1);
    value.erase(0, value.find_first_not_of(" \t\""));
    while (!value.empty() && (value.back() == '"' || value.back() == ' ')) value.pop_back();
    return value;
  }
  return "";
}

// A number from a /proc or /sys file (the first on the line that starts with `key`, or the
// file's first); "kB" scaled. False when absent or not a number ("max": no limit).
bool read_number(const char* file, const char* key, uint64_t* out) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (key && line.rfind(key, 0) != 0) continue;
    std::istringstream words(key ? line.substr(std::string(key).size()) : line);
    unsigned long long v = 0;
    if (!(words >> v)) return false;
    std::string unit;
    words >> unit;
    *out = unit == "kB" ? v * 1024 : v;
    return true;
  }
  return false;
}

}  // namespace

SystemFacts system_facts() {
  SystemFacts s;
  s.cpu_model = read_field("/proc/cpuinfo", "model name", ':');
  if (s.cpu_model.empty()) s.cpu_model = "unknown";
  const std::string mem_kb = read_field("/proc/meminfo", "MemTotal", ':');
  if (!mem_kb.empty()) s.memory_bytes = std::stoull(mem_kb) * 1024ull;
  s.os = read_field("/etc/os-release", "PRETTY_NAME", '=');
  utsname u{};
  if (uname(&u) == 0)
    s.os += (s.os.empty() ? "" : ", ") + std::string(u.sysname) + " " + u.release + " " + u.machine;
  return s;
}

std::vector<MemoryBound> memory_bounds() {
  std::vector<MemoryBound> bounds;
  struct rlimit as {};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    uint64_t used = 0;
    read_number("/proc/self/status", "VmSize:", &used);
    const uint64_t cap = static_cast<uint64_t>(as.rlim_cur);
    bounds.push_back({cap > used ? cap - used : 0, "the address-space limit (ulimit -v)", cap});
  }
  uint64_t cgroup_max = 0, cgroup_now = 0;
  if (read_number("/sys/fs/cgroup/memory.max", nullptr, &cgroup_max) &&
      read_number("/sys/fs/cgroup/memory.current", nullptr, &cgroup_now))
    bounds.push_back({cgroup_max > cgroup_now ? cgroup_max - cgroup_now : 0,
                      "the cgroup's memory.max", cgroup_max});
  uint64_t available = 0, swap_free = 0;
  if (read_number("/proc/meminfo", "MemAvailable:", &available)) {
    read_number("/proc/meminfo", "SwapFree:", &swap_free);
    bounds.push_back(
        {available + swap_free, "the memory available (MemAvailable and free swap)", 0});
  }
  return bounds;
}

uint64_t heap_bytes_in_use() {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer's allocator serves every malloc (a plugin's too); mallinfo2 reads zero.
  return __sanitizer_get_current_allocated_bytes();
#else
  // Small blocks from the arenas, and the large ones malloc maps on their own.
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
#endif
}

size_t threads_in_this_process() {
  std::error_code ec;
  size_t n = 0;
  for (std::filesystem::directory_iterator it("/proc/self/task", ec), end; !ec && it != end;
       it.increment(ec))
    ++n;
  return n;
}

std::string why_no_display() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((x && *x) || (wayland && *wayland)) return {};
  return "no display (DISPLAY and WAYLAND_DISPLAY are unset)";
}

}  // namespace fr
