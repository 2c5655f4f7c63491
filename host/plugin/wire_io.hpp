// wire_io.hpp — sending and receiving scene_wire frames over a channel (platform/channel.hpp).
#pragma once

#include "platform/channel.hpp"
#include "plugin/scene_wire.hpp"

#include <string>

namespace fr {

// Writes one frame; false when the other end is gone.
bool write_frame(Channel& channel, WireKind kind, const std::string& payload);

enum class ReadStatus { Ok, Closed, TimedOut, Malformed, Failed };

// Reads one frame, waiting at most `timeout_s` in total (a negative timeout waits forever).
// Takes whatever has arrived with the frame (one request, one answer: nothing else can have).
ReadStatus read_frame(Channel& channel, double timeout_s, WireKind* kind, std::string* payload);
// The same, reading no byte past the frame: for a peer that may send several frames in a row
// (the render worker's progress messages before its answer).
ReadStatus read_frame_exact(Channel& channel, double timeout_s, WireKind* kind,
                            std::string* payload);

}  // namespace fr
