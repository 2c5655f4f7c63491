// device.hpp — finding OpenCL devices and choosing one.
//
// Default: the first GPU if there is one, else the first CPU device (PoCL on machines without a
// GPU). A CPU device gets packets of 16 rays, four AVX-512 vectors where it has them (64 lanes in
// float, 32 in double), a GPU 1 lane (one pixel per work-item).
#pragma once

#include "render/cl.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fr {

struct DeviceInfo {
  cl_platform_id platform = nullptr;
  cl_device_id device = nullptr;
  int platform_index = 0;
  int device_index = 0;  // within its platform
  std::string platform_name;
  std::string name;
  std::string vendor;
  std::string version;         // CL_DEVICE_VERSION
  std::string driver_version;  // CL_DRIVER_VERSION
  cl_device_type type = 0;
  unsigned compute_units = 0;
  unsigned long long global_mem_bytes = 0;  // CL_DEVICE_GLOBAL_MEM_SIZE
  unsigned long long max_alloc_bytes = 0;   // CL_DEVICE_MAX_MEM_ALLOC_SIZE: one buffer's limit
  bool has_fp64 = false;
  unsigned native_float_width = 0;   // CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT: 16 with AVX-512
  unsigned native_double_width = 0;  // CL_DEVICE_NATIVE_VECTOR_WIDTH_DOUBLE: 8 with AVX-512

  bool is_gpu() const { return (type & CL_DEVICE_TYPE_GPU) != 0; }
  std::string type_name() const;
  // "0:1" — the selector that picks exactly this device.
  std::string selector() const;
};

// All devices of all platforms. No platform at all gives an empty list (not an error).
std::vector<DeviceInfo> list_devices();

// Picks a device. `selector`: "" (default), "gpu", "cpu", "P:D" (platform:device indices), or a
// case-insensitive part of the device name. On no match returns nullopt and sets *error.
std::optional<DeviceInfo> select_device(const std::vector<DeviceInfo>& devices,
                                        const std::string& selector, std::string* error);

enum class Precision;  // render_settings.hpp

// Lane width that suits the device: 1 on GPUs and accelerators (one pixel per work-item); on
// CPUs 16, and with AVX-512 (native vectors of 16 floats, 8 doubles) four native vectors: 64 in
// float, 32 in double (wide_lanes.cl: a ray's DE is a chain of dependent operations, and
// independent chains side by side keep the vector units busy). Not wider with AVX2: its 16
// registers of 8 floats already spill 16-lane values (docs/performance.md); and 16 in
// double-double, whose values are pairs.
int preferred_lanes(const DeviceInfo& device, Precision precision);

// The one rule for the lane width a kernel is built with: the requested width (render.lanes,
// --lanes) when set, else the device's preferred width; with no device at hand (describing a
// kernel without opening one), a CPU's.
int resolve_lanes(int requested, const DeviceInfo* device, Precision precision);

// The widest packet a scene's code is sure to build at: 32 and 64 lanes rely on wide_lanes.cl's
// overloads of the built-ins, which a scene's code may go beyond.
constexpr int kPacketLanes = 16;
// The width a CPU with AVX-512 renders float at: four of its vectors.
constexpr int kWideLanes = 64;

}  // namespace fr
