// system_info.hpp — the machine a benchmark ran on, read from the system and OpenCL.
#pragma once

#include "render/device.hpp"

#include <string>

namespace fr {

struct SystemInfo {
  std::string cpu_model;                // /proc/cpuinfo "model name"
  unsigned logical_cores = 0;           // std::thread::hardware_concurrency
  unsigned long long memory_bytes = 0;  // /proc/meminfo MemTotal
  std::string os;                       // /etc/os-release PRETTY_NAME, kernel release from uname
  std::string opencl_platform;
  std::string opencl_device;
  std::string opencl_device_version;  // CL_DEVICE_VERSION
  std::string opencl_driver;          // CL_DRIVER_VERSION
};

SystemInfo read_system_info(const DeviceInfo& device);

}  // namespace fr
