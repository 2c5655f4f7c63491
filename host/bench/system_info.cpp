#include "bench/system_info.hpp"

#include "platform/system_facts.hpp"

#include <thread>

namespace fr {

SystemInfo read_system_info(const DeviceInfo& device) {
  SystemInfo s;
  const SystemFacts facts = system_facts();
  s.cpu_model = facts.cpu_model;
  s.logical_cores = std::thread::hardware_concurrency();
  s.memory_bytes = facts.memory_bytes;
  s.os = facts.os;
  s.opencl_platform = device.platform_name;
  s.opencl_device = device.name;
  s.opencl_device_version = device.version;
  s.opencl_driver = device.driver_version;
  return s;
}

}  // namespace fr
