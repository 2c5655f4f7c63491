#include "plugin/wire_io.hpp"

#include <chrono>
#include <cmath>
#include <cstring>

namespace fr {
namespace {

using Clock = std::chrono::steady_clock;

ReadStatus status_of(ChannelStatus s) {
  switch (s) {
    case ChannelStatus::Ok:
      return ReadStatus::Ok;
    case ChannelStatus::Closed:
      return ReadStatus::Closed;
    case ChannelStatus::TimedOut:
      return ReadStatus::TimedOut;
    case ChannelStatus::Failed:
      break;
  }
  return ReadStatus::Failed;
}

ReadStatus read_exactly(Channel& channel, char* out, size_t n, Clock::time_point deadline,
                        bool forever) {
  // An answer usually comes within tens of microseconds: looking for it for a short while costs
  // less than sleeping in the system and being woken (which is most of a round trip's time).
  const auto spin_until = Clock::now() + std::chrono::microseconds(forever ? 0 : 200);
  while (n > 0 && Clock::now() < spin_until) {
    size_t got = 0;
    const ChannelStatus s = channel.read_some(out, n, 0, &got);
    if (s == ChannelStatus::Ok) {
      out += got;
      n -= got;
    } else if (s != ChannelStatus::TimedOut) {
      return status_of(s);
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
    size_t got = 0;
    const ChannelStatus s = channel.read_some(out, n, wait_ms, &got);
    if (s != ChannelStatus::Ok) return status_of(s);
    out += got;
    n -= got;
  }
  return ReadStatus::Ok;
}

}  // namespace

// One write per frame: the other side wakes once per message (this is most of an update's
// round-trip time).
bool write_frame(Channel& channel, WireKind kind, const std::string& payload) {
  if (payload.size() > kMaxFrameBytes) return false;
  const uint32_t header[2] = {static_cast<uint32_t>(kind), static_cast<uint32_t>(payload.size())};
  std::string frame(reinterpret_cast<const char*>(header), sizeof header);
  frame += payload;
  return channel.write_all(frame.data(), frame.size());
}

ReadStatus read_frame(Channel& channel, double timeout_s, WireKind* kind, std::string* payload) {
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
    ReadStatus s = read_exactly(channel, first + got, 1, deadline, forever);
    if (s != ReadStatus::Ok) return s;
    ++got;
    size_t more = 0;
    if (channel.read_some(first + got, want - 1, 0, &more) == ChannelStatus::Ok) got += more;
  }
  uint32_t header[2];
  std::memcpy(header, first, sizeof header);
  if (header[1] > kMaxFrameBytes || got - 8 > header[1]) return ReadStatus::Malformed;
  payload->assign(first + 8, got - 8);
  const size_t have = payload->size();
  payload->resize(header[1]);
  const ReadStatus s =
      read_exactly(channel, payload->data() + have, payload->size() - have, deadline, forever);
  if (s != ReadStatus::Ok) return s;
  *kind = static_cast<WireKind>(header[0]);
  return ReadStatus::Ok;
}

ReadStatus read_frame_exact(Channel& channel, double timeout_s, WireKind* kind,
                            std::string* payload) {
  const bool forever = timeout_s < 0;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(forever ? 0.0 : timeout_s));
  uint32_t header[2];
  ReadStatus s =
      read_exactly(channel, reinterpret_cast<char*>(header), sizeof header, deadline, forever);
  if (s != ReadStatus::Ok) return s;
  if (header[1] > kMaxFrameBytes) return ReadStatus::Malformed;
  payload->resize(header[1]);
  s = read_exactly(channel, payload->data(), payload->size(), deadline, forever);
  if (s != ReadStatus::Ok) return s;
  *kind = static_cast<WireKind>(header[0]);
  return ReadStatus::Ok;
}

}  // namespace fr
