#include "platform/shared_memory.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace fr {
namespace {

// Maps `bytes` of descriptor `fd` in place of the old mapping; false with *error.
bool remap(int fd, size_t bytes, uint8_t** data, size_t* mapped, std::string* error) {
  if (*data) munmap(*data, *mapped);
  *data = nullptr;
  *mapped = 0;
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (p == MAP_FAILED) {
    *error = std::string("cannot map the shared frame: ") + std::strerror(errno);
    return false;
  }
  *data = static_cast<uint8_t*>(p);
  *mapped = bytes;
  return true;
}

}  // namespace

SharedMemory::SharedMemory() {
  const int fd = memfd_create("fractalis-frame", MFD_CLOEXEC | MFD_ALLOW_SEALING);
  if (fd < 0)
    throw std::runtime_error(std::string("cannot create the render worker's shared frame: ") +
                             std::strerror(errno));
  if (fcntl(fd, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_SEAL) != 0) {
    const int e = errno;
    close(fd);
    throw std::runtime_error(std::string("cannot seal the render worker's shared frame: ") +
                             std::strerror(e));
  }
  handle_ = fd;
}

SharedMemory::SharedMemory(intptr_t handle) : handle_(handle) {}

SharedMemory::~SharedMemory() {
  if (data_) munmap(data_, mapped_);
  if (handle_ >= 0) close(static_cast<int>(handle_));
}

void SharedMemory::grow(size_t bytes) {
  if (bytes <= mapped_) return;
  const size_t target = bytes + bytes / 4;
  if (ftruncate(static_cast<int>(handle_), static_cast<off_t>(target)) != 0)
    throw std::runtime_error("cannot make the shared frame " + std::to_string(target >> 20) +
                             " MiB: " + std::strerror(errno));
  std::string error;
  if (!remap(static_cast<int>(handle_), target, &data_, &mapped_, &error))
    throw std::runtime_error(error);
}

intptr_t SharedMemory::duplicate_handle() const {
  return fcntl(static_cast<int>(handle_), F_DUPFD_CLOEXEC, 0);
}

bool SharedMemory::map_at_least(size_t bytes, std::string* error) {
  if (bytes <= mapped_) return true;
  struct stat st {};
  if (fstat(static_cast<int>(handle_), &st) != 0 || static_cast<size_t>(st.st_size) < bytes) {
    *error = "the shared frame is smaller than the frame asked for";
    return false;
  }
  return remap(static_cast<int>(handle_), static_cast<size_t>(st.st_size), &data_, &mapped_, error);
}

}  // namespace fr
