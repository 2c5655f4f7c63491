// memory_budget.hpp — whether an image of a given size fits, checked before any work.
//
// A render of W x H pixels allocates the renderer's device buffers (renderer.cpp's
// ensure_buffers) and, on the host, the read-back copies and the PNG encoder's buffers. Too
// large a size used to fail late and badly: a buffer over the device's one-allocation limit came
// back as CL_INVALID_BUFFER_SIZE after the kernel build, and under an address-space limit
// (ulimit -v) PoCL's lazy allocation ended the process with an assertion. Checked up front
// instead, against the device's limits and the process's memory, with the limit named.
#pragma once

#include "render/device.hpp"

#include <cstdint>
#include <string>

namespace fr {

struct MemoryNeed {
  uint64_t largest_buffer_bytes = 0;  // the HDR image: 16 bytes a pixel
  uint64_t device_bytes = 0;          // every device buffer
  uint64_t host_bytes = 0;            // read-back copies and the PNG encoder's buffers
};

// What rendering `width_px` x `height_px` and writing it as PNG (with every pass read back when
// `all_passes`) needs.
MemoryNeed render_memory_need(int width_px, int height_px, bool all_passes);

// Memory the process can still get: the least of the address-space limit's headroom (ulimit -v),
// the cgroup's memory.max headroom and MemAvailable plus free swap; ~0 when none is known. `why`
// names the limit that binds.
uint64_t process_memory_headroom(std::string* why);

// Why `need` cannot be met on `device` in this process ("needs 4.0 GiB for the HDR image, more
// than the device's largest allocation (CL_DEVICE_MAX_MEM_ALLOC_SIZE) of 1.2 GiB"), or "".
std::string memory_problem(const MemoryNeed& need, const DeviceInfo& device);

// "1.5 GiB", "300 MiB", "12 KiB".
std::string format_bytes(uint64_t bytes);

}  // namespace fr
