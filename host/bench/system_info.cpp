#include "bench/system_info.hpp"

#include <sys/utsname.h>

#include <fstream>
#include <thread>

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

}  // namespace

SystemInfo read_system_info(const DeviceInfo& device) {
  SystemInfo s;
  s.cpu_model = read_field("/proc/cpuinfo", "model name", ':');
  if (s.cpu_model.empty()) s.cpu_model = "unknown";
  s.logical_cores = std::thread::hardware_concurrency();
  const std::string mem_kb = read_field("/proc/meminfo", "MemTotal", ':');
  if (!mem_kb.empty()) s.memory_bytes = std::stoull(mem_kb) * 1024ull;
  s.os = read_field("/etc/os-release", "PRETTY_NAME", '=');
  utsname u{};
  if (uname(&u) == 0)
    s.os += (s.os.empty() ? "" : ", ") + std::string(u.sysname) + " " + u.release + " " + u.machine;
  s.opencl_platform = device.platform_name;
  s.opencl_device = device.name;
  s.opencl_device_version = device.version;
  s.opencl_driver = device.driver_version;
  return s;
}

}  // namespace fr
