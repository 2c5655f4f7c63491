#include "platform/shared_memory.hpp"

#include "platform/last_error_windows.hpp"

#include <windows.h>

#include <stdexcept>

namespace fr {
namespace {

// A section cannot grow, so it is made as large as any frame may need, with its pages only
// reserved (no memory, no page file): grow() commits the ones a frame uses. The view is the
// same size in both processes; pages a side touches beyond what is committed fault there only.
constexpr uint64_t kReservedBytes = uint64_t{16} << 30;

HANDLE as_handle(intptr_t h) {
  return reinterpret_cast<HANDLE>(h);
}

uint8_t* map_whole(intptr_t handle) {
  return static_cast<uint8_t*>(MapViewOfFile(as_handle(handle), FILE_MAP_ALL_ACCESS, 0, 0, 0));
}

}  // namespace

SharedMemory::SharedMemory() {
  const HANDLE section =
      CreateFileMappingW(INVALID_HANDLE_VALUE, nullptr, PAGE_READWRITE | SEC_RESERVE,
                         static_cast<DWORD>(kReservedBytes >> 32),
                         static_cast<DWORD>(kReservedBytes & 0xffffffffu), nullptr);
  if (!section)
    throw std::runtime_error("cannot create the render worker's shared frame: " +
                             last_error_text());
  handle_ = reinterpret_cast<intptr_t>(section);
  data_ = map_whole(handle_);
  if (!data_) {
    const std::string why = last_error_text();
    CloseHandle(section);
    handle_ = -1;
    throw std::runtime_error("cannot map the render worker's shared frame: " + why);
  }
}

SharedMemory::SharedMemory(intptr_t handle) : handle_(handle) {}

SharedMemory::~SharedMemory() {
  if (data_) UnmapViewOfFile(data_);
  if (handle_ != -1) CloseHandle(as_handle(handle_));
}

void SharedMemory::grow(size_t bytes) {
  if (bytes <= mapped_) return;
  const size_t target = bytes + bytes / 4;
  if (target > kReservedBytes || !VirtualAlloc(data_, target, MEM_COMMIT, PAGE_READWRITE))
    throw std::runtime_error(
        "cannot make the shared frame " + std::to_string(target >> 20) + " MiB: " +
        (target > kReservedBytes ? std::string("more than reserved") : last_error_text()));
  mapped_ = target;
}

intptr_t SharedMemory::duplicate_handle() const {
  HANDLE copy = nullptr;
  if (!DuplicateHandle(GetCurrentProcess(), as_handle(handle_), GetCurrentProcess(), &copy, 0,
                       FALSE, DUPLICATE_SAME_ACCESS))
    return -1;
  return reinterpret_cast<intptr_t>(copy);
}

bool SharedMemory::map_at_least(size_t bytes, std::string* error) {
  if (bytes <= mapped_) return true;
  if (!data_) data_ = map_whole(handle_);
  if (!data_) {
    *error = "cannot map the shared frame: " + last_error_text();
    return false;
  }
  // What fractalis committed is one region at the start of the view.
  MEMORY_BASIC_INFORMATION region{};
  if (VirtualQuery(data_, &region, sizeof region) == 0 || region.State != MEM_COMMIT ||
      region.RegionSize < bytes) {
    *error = "the shared frame is smaller than the frame asked for";
    return false;
  }
  mapped_ = region.RegionSize;
  return true;
}

}  // namespace fr
