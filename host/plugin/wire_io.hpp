// wire_io.hpp — sending and receiving scene_wire frames over a socket.
#pragma once

#include "plugin/scene_wire.hpp"

#include <string>

namespace fr {

// Writes one frame; false when the other end is gone (never raises SIGPIPE).
bool write_frame(int fd, WireKind kind, const std::string& payload);

enum class ReadStatus { Ok, Closed, TimedOut, Malformed, Failed };

// Reads one frame, waiting at most `timeout_s` in total (a negative timeout waits forever).
ReadStatus read_frame(int fd, double timeout_s, WireKind* kind, std::string* payload);

}  // namespace fr
