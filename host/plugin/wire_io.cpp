#include "plugin/wire_io.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>

namespace fr {
namespace {

bool write_all(int fd, const char* data, size_t n) {
  while (n > 0) {
    const ssize_t w = send(fd, data, n, MSG_NOSIGNAL);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}

using Clock = std::chrono::steady_clock;

ReadStatus read_exactly(int fd, char* out, size_t n, Clock::time_point deadline, bool forever) {
  while (n > 0) {
    int wait_ms = -1;
    if (!forever) {
      const double left_ms =
          std::chrono::duration<double, std::milli>(deadline - Clock::now()).count();
      // Past the deadline there is still one look: an answer may already be waiting.
      wait_ms = left_ms <= 0 ? 0 : static_cast<int>(std::ceil(left_ms));
    }
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, wait_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return ReadStatus::Failed;
    if (ready == 0) return ReadStatus::TimedOut;
    const ssize_t r = read(fd, out, n);
    if (r < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (r < 0) return errno == ECONNRESET ? ReadStatus::Closed : ReadStatus::Failed;
    if (r == 0) return ReadStatus::Closed;
    out += r;
    n -= static_cast<size_t>(r);
  }
  return ReadStatus::Ok;
}

}  // namespace

bool write_frame(int fd, WireKind kind, const std::string& payload) {
  if (payload.size() > kMaxFrameBytes) return false;
  const uint32_t header[2] = {static_cast<uint32_t>(kind), static_cast<uint32_t>(payload.size())};
  return write_all(fd, reinterpret_cast<const char*>(header), sizeof header) &&
         write_all(fd, payload.data(), payload.size());
}

ReadStatus read_frame(int fd, double timeout_s, WireKind* kind, std::string* payload) {
  const bool forever = timeout_s < 0;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(forever ? 0.0 : timeout_s));
  uint32_t header[2] = {};
  ReadStatus s = read_exactly(fd, reinterpret_cast<char*>(header), sizeof header, deadline, forever);
  if (s != ReadStatus::Ok) return s;
  if (header[1] > kMaxFrameBytes) return ReadStatus::Malformed;
  payload->assign(header[1], '\0');
  s = read_exactly(fd, payload->data(), payload->size(), deadline, forever);
  if (s != ReadStatus::Ok) return s;
  *kind = static_cast<WireKind>(header[0]);
  return ReadStatus::Ok;
}

}  // namespace fr
