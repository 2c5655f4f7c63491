// shared_frame.hpp — the memory a render worker reads a frame back into, mapped by both ends.
//
// fractalis creates it (an anonymous memfd, never a name in /dev/shm that another process could
// open or that could outlive a crash) and hands the worker its descriptor at start. It only
// grows: fractalis grows it before asking for a frame larger than it is, and seals it against
// shrinking, so a worker that truncates it cannot make fractalis's reads fault (SIGBUS).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace fr {

class SharedFrame {
 public:
  // Creates an empty one; throws std::runtime_error when the system refuses.
  SharedFrame();
  // Maps the one open at `fd` (the worker's side); takes the descriptor.
  explicit SharedFrame(int fd);
  ~SharedFrame();
  SharedFrame(const SharedFrame&) = delete;
  SharedFrame& operator=(const SharedFrame&) = delete;

  // fractalis: makes it at least `bytes` long. Throws std::runtime_error when it cannot.
  void grow(size_t bytes);
  // The worker: maps at least `bytes` of it; false with *error when it is shorter or unmappable.
  bool map_at_least(size_t bytes, std::string* error);

  uint8_t* data() const { return data_; }
  size_t mapped_bytes() const { return mapped_; }
  int fd() const { return fd_; }

 private:
  bool map(size_t bytes, std::string* error);
  int fd_ = -1;
  uint8_t* data_ = nullptr;
  size_t mapped_ = 0;
};

}  // namespace fr
