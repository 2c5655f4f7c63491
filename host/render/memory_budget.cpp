#include "render/memory_budget.hpp"

#include "platform/system_facts.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace fr {
namespace {

// Bytes per pixel of renderer.cpp's buffers: HDR float4, depth, steps, AO and shadow factors,
// ray status, normal float3, albedo float3, display RGBA8.
constexpr uint64_t kDeviceBytesPerPixel = 16 + 4 + 4 + 8 + 1 + 12 + 12 + 4;
// Read-back copies (FrameImage): RGBA8, steps, status; with every pass also linear RGBA, depth,
// factors, normal, albedo, occlusion and shadow.
constexpr uint64_t kDisplayReadbackBytesPerPixel = 4 + 4 + 1;
constexpr uint64_t kAllPassesReadbackBytesPerPixel = 16 + 4 + 8 + 12 + 12 + 4 + 4;
// The PNG encoder: its filtered copy of the image, the compressed stream and our copy of it.
constexpr uint64_t kPngBytesPerPixel = 4 + 4 + 4;

}  // namespace

MemoryNeed render_memory_need(int width_px, int height_px, bool all_passes) {
  const uint64_t pixels =
      static_cast<uint64_t>(std::max(width_px, 0)) * static_cast<uint64_t>(std::max(height_px, 0));
  MemoryNeed need;
  need.largest_buffer_bytes = pixels * 16;
  need.device_bytes = pixels * kDeviceBytesPerPixel;
  need.host_bytes = pixels * (kDisplayReadbackBytesPerPixel + kPngBytesPerPixel +
                              (all_passes ? kAllPassesReadbackBytesPerPixel : 0));
  return need;
}

uint64_t process_memory_headroom(std::string* why) {
  uint64_t headroom = std::numeric_limits<uint64_t>::max();
  auto limit = [&](uint64_t bytes, const std::string& name) {
    if (bytes < headroom) headroom = bytes, *why = name;
  };
  for (const MemoryBound& b : memory_bounds())
    limit(b.bytes_left,
          b.cap_bytes ? "what " + b.name + ", " + format_bytes(b.cap_bytes) + ", leaves" : b.name);
  return headroom;
}

std::string memory_problem(const MemoryNeed& need, const DeviceInfo& device) {
  if (device.max_alloc_bytes > 0 && need.largest_buffer_bytes > device.max_alloc_bytes)
    return "needs " + format_bytes(need.largest_buffer_bytes) +
           " for the HDR image, more than the device's largest allocation "
           "(CL_DEVICE_MAX_MEM_ALLOC_SIZE) of " +
           format_bytes(device.max_alloc_bytes);
  if (device.global_mem_bytes > 0 && need.device_bytes > device.global_mem_bytes)
    return "needs " + format_bytes(need.device_bytes) +
           " of device buffers, more than the device's memory (CL_DEVICE_GLOBAL_MEM_SIZE) of " +
           format_bytes(device.global_mem_bytes);
  // A CPU device's buffers are this process's memory too.
  const uint64_t process_bytes = need.host_bytes + (device.is_gpu() ? 0 : need.device_bytes);
  std::string why;
  const uint64_t headroom = process_memory_headroom(&why);
  if (process_bytes > headroom)
    return "needs " + format_bytes(process_bytes) + " of memory, more than " + why + ": " +
           format_bytes(headroom);
  return "";
}

std::string format_bytes(uint64_t bytes) {
  char text[32];
  if (bytes >= (1ull << 30))
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1ull << 30));
  else if (bytes >= (1ull << 20))
    std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1ull << 20));
  else
    std::snprintf(text, sizeof text, "%.0f KiB", static_cast<double>(bytes) / (1ull << 10));
  return text;
}

}  // namespace fr
