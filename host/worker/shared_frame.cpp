#include "worker/shared_frame.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace fr {

SharedFrame::SharedFrame() {
  fd_ = memfd_create("fractalis-frame", MFD_CLOEXEC | MFD_ALLOW_SEALING);
  if (fd_ < 0)
    throw std::runtime_error(std::string("cannot create the render worker's shared frame: ") +
                             std::strerror(errno));
  if (fcntl(fd_, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_SEAL) != 0) {
    const int e = errno;
    close(fd_);
    throw std::runtime_error(std::string("cannot seal the render worker's shared frame: ") +
                             std::strerror(e));
  }
}

SharedFrame::SharedFrame(int fd) : fd_(fd) {}

SharedFrame::~SharedFrame() {
  if (data_) munmap(data_, mapped_);
  if (fd_ >= 0) close(fd_);
}

bool SharedFrame::map(size_t bytes, std::string* error) {
  if (data_) munmap(data_, mapped_);
  data_ = nullptr;
  mapped_ = 0;
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
  if (p == MAP_FAILED) {
    *error = std::string("cannot map the shared frame: ") + std::strerror(errno);
    return false;
  }
  data_ = static_cast<uint8_t*>(p);
  mapped_ = bytes;
  return true;
}

void SharedFrame::grow(size_t bytes) {
  if (bytes <= mapped_) return;
  // In steps of a quarter more than asked, so that a frame that grows a little at a time (the
  // explorer's resolution scale) does not remap every frame.
  const size_t target = bytes + bytes / 4;
  std::string error;
  if (ftruncate(fd_, static_cast<off_t>(target)) != 0)
    throw std::runtime_error("cannot make the shared frame " + std::to_string(target >> 20) +
                             " MiB: " + std::strerror(errno));
  if (!map(target, &error)) throw std::runtime_error(error);
}

bool SharedFrame::map_at_least(size_t bytes, std::string* error) {
  if (bytes <= mapped_) return true;
  struct stat st {};
  if (fstat(fd_, &st) != 0 || static_cast<size_t>(st.st_size) < bytes) {
    *error = "the shared frame is smaller than the frame asked for";
    return false;
  }
  return map(static_cast<size_t>(st.st_size), error);
}

}  // namespace fr
