// shared_memory.hpp — memory that fractalis and a helper process (the render worker) both map.
//
// fractalis creates it and makes it larger as frames grow; the helper maps the handle it was
// given at start, as much of it as a request says it needs, and refuses a request for more than
// there is. It never shrinks (sealed on Linux; a Windows section cannot), so a helper cannot
// make fractalis's reads of it fault. Nothing outside the two processes can open it: an anonymous
// memfd on Linux, a section without a name on Windows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace fr {

class SharedMemory {
 public:
  // fractalis's side: empty, to be grown. Throws std::runtime_error when the system refuses.
  SharedMemory();
  // The helper's side: the memory behind `handle` (a descriptor, or a HANDLE), which it takes.
  explicit SharedMemory(intptr_t handle);
  ~SharedMemory();
  SharedMemory(const SharedMemory&) = delete;
  SharedMemory& operator=(const SharedMemory&) = delete;

  // fractalis: at least `bytes` usable (a quarter more, so that a frame growing a little at a
  // time does not remap every frame). Throws std::runtime_error when it cannot.
  void grow(size_t bytes);
  // The helper: maps at least `bytes` of it; false with *error when it is smaller or unmappable.
  bool map_at_least(size_t bytes, std::string* error);

  uint8_t* data() const { return data_; }
  size_t mapped_bytes() const { return mapped_; }
  // What to hand the helper (inheritable only where the process layer makes it so).
  intptr_t handle() const { return handle_; }
  // A second handle to the same memory, owned by whoever takes it (-1 when the system refuses).
  intptr_t duplicate_handle() const;

 private:
  intptr_t handle_ = -1;
  uint8_t* data_ = nullptr;
  size_t mapped_ = 0;
};

}  // namespace fr
