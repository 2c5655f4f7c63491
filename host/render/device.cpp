#include "render/device.hpp"

#include "render/render_settings.hpp"

#include <algorithm>
#include <cctype>

namespace fr {
namespace {

std::string device_string(cl_device_id d, cl_device_info what) {
  size_t size = 0;
  if (clGetDeviceInfo(d, what, 0, nullptr, &size) != CL_SUCCESS || size == 0) return "";
  std::string s(size, '\0');
  clGetDeviceInfo(d, what, size, s.data(), nullptr);
  while (!s.empty() && (s.back() == '\0' || s.back() == ' ')) s.pop_back();
  return s;
}

std::string platform_string(cl_platform_id p, cl_platform_info what) {
  size_t size = 0;
  if (clGetPlatformInfo(p, what, 0, nullptr, &size) != CL_SUCCESS || size == 0) return "";
  std::string s(size, '\0');
  clGetPlatformInfo(p, what, size, s.data(), nullptr);
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

std::string DeviceInfo::type_name() const {
  if (type & CL_DEVICE_TYPE_GPU) return "GPU";
  if (type & CL_DEVICE_TYPE_CPU) return "CPU";
  if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

std::string DeviceInfo::selector() const {
  return std::to_string(platform_index) + ":" + std::to_string(device_index);
}

std::vector<DeviceInfo> list_devices() {
  std::vector<DeviceInfo> out;
  cl_uint platform_count = 0;
  if (clGetPlatformIDs(0, nullptr, &platform_count) != CL_SUCCESS || platform_count == 0)
    return out;
  std::vector<cl_platform_id> platforms(platform_count);
  cl_check(clGetPlatformIDs(platform_count, platforms.data(), nullptr), "clGetPlatformIDs");
  for (cl_uint pi = 0; pi < platform_count; ++pi) {
    cl_uint device_count = 0;
    if (clGetDeviceIDs(platforms[pi], CL_DEVICE_TYPE_ALL, 0, nullptr, &device_count) != CL_SUCCESS)
      continue;
    std::vector<cl_device_id> devices(device_count);
    cl_check(
        clGetDeviceIDs(platforms[pi], CL_DEVICE_TYPE_ALL, device_count, devices.data(), nullptr),
        "clGetDeviceIDs");
    for (cl_uint di = 0; di < device_count; ++di) {
      DeviceInfo info;
      info.platform = platforms[pi];
      info.device = devices[di];
      info.platform_index = static_cast<int>(pi);
      info.device_index = static_cast<int>(di);
      info.platform_name = platform_string(platforms[pi], CL_PLATFORM_NAME);
      info.name = device_string(devices[di], CL_DEVICE_NAME);
      info.vendor = device_string(devices[di], CL_DEVICE_VENDOR);
      info.version = device_string(devices[di], CL_DEVICE_VERSION);
      info.driver_version = device_string(devices[di], CL_DRIVER_VERSION);
      clGetDeviceInfo(devices[di], CL_DEVICE_TYPE, sizeof info.type, &info.type, nullptr);
      cl_uint units = 0;
      clGetDeviceInfo(devices[di], CL_DEVICE_MAX_COMPUTE_UNITS, sizeof units, &units, nullptr);
      info.compute_units = units;
      cl_ulong mem = 0;
      clGetDeviceInfo(devices[di], CL_DEVICE_GLOBAL_MEM_SIZE, sizeof mem, &mem, nullptr);
      info.global_mem_bytes = mem;
      cl_ulong max_alloc = 0;
      clGetDeviceInfo(devices[di], CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof max_alloc, &max_alloc,
                      nullptr);
      info.max_alloc_bytes = max_alloc;
      info.has_fp64 =
          device_string(devices[di], CL_DEVICE_EXTENSIONS).find("cl_khr_fp64") != std::string::npos;
      cl_uint float_width = 0;
      clGetDeviceInfo(devices[di], CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT, sizeof float_width,
                      &float_width, nullptr);
      info.native_float_width = float_width;
      cl_uint double_width = 0;
      clGetDeviceInfo(devices[di], CL_DEVICE_NATIVE_VECTOR_WIDTH_DOUBLE, sizeof double_width,
                      &double_width, nullptr);
      info.native_double_width = double_width;
      out.push_back(std::move(info));
    }
  }
  return out;
}

std::optional<DeviceInfo> select_device(const std::vector<DeviceInfo>& devices,
                                        const std::string& selector, std::string* error) {
  if (devices.empty()) {
    *error = "no OpenCL device found (is an ICD such as pocl-opencl-icd installed?)";
    return std::nullopt;
  }
  const std::string sel = lower(selector);
  auto first_of = [&](cl_device_type t) -> std::optional<DeviceInfo> {
    for (const auto& d : devices)
      if (d.type & t) return d;
    return std::nullopt;
  };
  if (sel.empty()) {
    if (auto gpu = first_of(CL_DEVICE_TYPE_GPU)) return gpu;
    if (auto cpu = first_of(CL_DEVICE_TYPE_CPU)) return cpu;
    return devices.front();
  }
  if (sel == "gpu" || sel == "cpu") {
    if (auto d = first_of(sel == "gpu" ? CL_DEVICE_TYPE_GPU : CL_DEVICE_TYPE_CPU)) return d;
    *error = "--device " + selector + ": no " + sel + " device (see `fractalis devices`)";
    return std::nullopt;
  }
  for (const auto& d : devices)
    if (d.selector() == sel) return d;
  for (const auto& d : devices)
    if (lower(d.name).find(sel) != std::string::npos) return d;
  *error =
      "--device " + selector +
      ": matches no device (expected gpu, cpu, P:D or part of a name; see `fractalis devices`)";
  return std::nullopt;
}

int preferred_lanes(const DeviceInfo& device, Precision precision) {
  if (!(device.type & CL_DEVICE_TYPE_CPU)) return 1;
  if (precision == Precision::DoubleDouble) return kPacketLanes;
  if (precision == Precision::Double) return device.native_double_width >= 8 ? 32 : kPacketLanes;
  return device.native_float_width >= 16 ? kWideLanes : kPacketLanes;
}

int resolve_lanes(int requested, const DeviceInfo* device, Precision precision) {
  if (requested > 0) return requested;
  DeviceInfo cpu;
  cpu.type = CL_DEVICE_TYPE_CPU;
  return preferred_lanes(device ? *device : cpu, precision);
}

}  // namespace fr
