// channel.hpp — byte streams between fractalis and its helper processes.
//
// A channel is one end of a two-way stream (the wire to a scene host or the render worker) or of
// a one-way pipe (a helper's stdout). fractalis makes the pair, keeps `ours` and gives `theirs`
// to the child it starts (child_process.hpp), which adopts it from the number its command line
// names. Linux: a socketpair or a pipe. Windows: a named pipe with an unguessable name, one
// instance only, opened for overlapped I/O so that a read can wait with a time limit.
//
// A Channel belongs to one thread at a time; reads and writes never raise a signal.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace fr {

// A system handle: a descriptor on Linux, a HANDLE on Windows. kNoHandle: none.
using NativeHandle = intptr_t;
constexpr NativeHandle kNoHandle = -1;

enum class ChannelStatus {
  Ok,        // bytes were read
  Closed,    // the other end is gone and everything it sent has been read
  TimedOut,  // nothing arrived within the time
  Failed,    // the system reported an error
};

class Channel {
 public:
  Channel() = default;
  // Takes `adopted` (a child: the handle its command line names).
  explicit Channel(NativeHandle adopted);
  ~Channel();
  Channel(Channel&& other) noexcept;
  Channel& operator=(Channel&& other) noexcept;
  Channel(const Channel&) = delete;
  Channel& operator=(const Channel&) = delete;

  bool is_open() const { return handle_ != kNoHandle; }
  // What child_process.hpp hands a child; still owned here.
  NativeHandle handle() const { return handle_; }
  void close();

  // Sends all `size` bytes; false once the other end is gone.
  bool write_all(const void* data, size_t size);
  // Reads what has arrived, at most `size` bytes (*got of them), waiting at most `timeout_ms`
  // for the first byte: negative waits for ever, 0 only looks.
  ChannelStatus read_some(void* data, size_t size, int timeout_ms, size_t* got);

 private:
  NativeHandle handle_ = kNoHandle;
  // Windows only: the events its overlapped reads and writes signal when they end.
  [[maybe_unused]] NativeHandle read_event_ = kNoHandle;
  [[maybe_unused]] NativeHandle write_event_ = kNoHandle;
};

struct ChannelPair {
  Channel ours;
  Channel theirs;  // for the child
};

// A two-way stream. False with *error when the system refuses.
bool make_channel_pair(ChannelPair* pair, std::string* error);
// A one-way pipe: `ours` reads what `theirs` (a child's stdout or stderr) writes.
bool make_pipe(ChannelPair* pair, std::string* error);

// Waits at most `timeout_ms` (negative: for ever) until one of `channels` has something to read
// or its other end has gone; returns its index, or -1 when none did in time. Closed channels
// are skipped, and so is any past the 16th.
int wait_readable(Channel* const* channels, size_t count, int timeout_ms);

}  // namespace fr
