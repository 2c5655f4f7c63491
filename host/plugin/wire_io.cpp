#include "plugin/wire_io.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>

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
  // An answer usually comes within tens of microseconds: looking for it for a short while costs
  // less than sleeping in poll and being woken (which is most of a round trip's time).
  const auto spin_until = Clock::now() + std::chrono::microseconds(forever ? 0 : 200);
  while (n > 0 && Clock::now() < spin_until) {
    const ssize_t r = recv(fd, out, n, MSG_DONTWAIT);
    if (r > 0) {
      out += r;
      n -= static_cast<size_t>(r);
    } else if (r == 0) {
      return ReadStatus::Closed;
    } else if (errno != EAGAIN && errno != EINTR) {
      break;  // poll and read below report it
    }
  }
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

// One write per frame: the other side wakes once per message (this is most of an update's
// round-trip time).
bool write_frame(int fd, WireKind kind, const std::string& payload) {
  if (payload.size() > kMaxFrameBytes) return false;
  const uint32_t header[2] = {static_cast<uint32_t>(kind), static_cast<uint32_t>(payload.size())};
  std::string frame(reinterpret_cast<const char*>(header), sizeof header);
  frame += payload;
  return write_all(fd, frame.data(), frame.size());
}

ReadStatus read_frame(int fd, double timeout_s, WireKind* kind, std::string* payload) {
  const bool forever = timeout_s < 0;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(forever ? 0.0 : timeout_s));
  // The protocol is strictly one request, one answer, so whatever has arrived belongs to this
  // frame: a first read takes the header and, usually, the whole payload with it.
  char first[4096];
  size_t got = 0;
  while (got < 8) {
    const size_t want = sizeof first - got;
    ReadStatus s = read_exactly(fd, first + got, 1, deadline, forever);
    if (s != ReadStatus::Ok) return s;
    ++got;
    const ssize_t more = recv(fd, first + got, want - 1, MSG_DONTWAIT);
    if (more > 0) got += static_cast<size_t>(more);
  }
  uint32_t header[2];
  std::memcpy(header, first, sizeof header);
  if (header[1] > kMaxFrameBytes || got - 8 > header[1]) return ReadStatus::Malformed;
  payload->assign(first + 8, got - 8);
  const size_t have = payload->size();
  payload->resize(header[1]);
  const ReadStatus s =
      read_exactly(fd, payload->data() + have, payload->size() - have, deadline, forever);
  if (s != ReadStatus::Ok) return s;
  *kind = static_cast<WireKind>(header[0]);
  return ReadStatus::Ok;
}

ReadStatus read_frame_exact(int fd, double timeout_s, WireKind* kind, std::string* payload) {
  const bool forever = timeout_s < 0;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(forever ? 0.0 : timeout_s));
  uint32_t header[2];
  ReadStatus s =
      read_exactly(fd, reinterpret_cast<char*>(header), sizeof header, deadline, forever);
  if (s != ReadStatus::Ok) return s;
  if (header[1] > kMaxFrameBytes) return ReadStatus::Malformed;
  payload->resize(header[1]);
  s = read_exactly(fd, payload->data(), payload->size(), deadline, forever);
  if (s != ReadStatus::Ok) return s;
  *kind = static_cast<WireKind>(header[0]);
  return ReadStatus::Ok;
}

}  // namespace fr
