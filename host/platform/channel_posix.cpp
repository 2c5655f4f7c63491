#include "platform/channel.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace fr {
namespace {

int fd_of(NativeHandle h) {
  return static_cast<int>(h);
}

// write() without SIGPIPE: a pipe has no MSG_NOSIGNAL, so the signal is blocked in this thread
// for the write, and one the write raised is taken back before the mask is restored.
ssize_t write_without_signal(int fd, const void* data, size_t size) {
  sigset_t pipe_only, old;
  sigemptyset(&pipe_only);
  sigaddset(&pipe_only, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_only, &old);
  const ssize_t w = write(fd, data, size);
  const int saved = errno;
  if (w < 0 && saved == EPIPE && !sigismember(&old, SIGPIPE)) {
    const timespec now{0, 0};
    sigtimedwait(&pipe_only, nullptr, &now);
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  errno = saved;
  return w;
}

bool refused(const char* what, std::string* error) {
  *error = std::string(what) + ": " + std::strerror(errno);
  return false;
}

}  // namespace

Channel::Channel(NativeHandle adopted) : handle_(adopted) {}

Channel::~Channel() {
  close();
}

Channel::Channel(Channel&& other) noexcept : handle_(std::exchange(other.handle_, kNoHandle)) {}

Channel& Channel::operator=(Channel&& other) noexcept {
  if (this != &other) {
    close();
    handle_ = std::exchange(other.handle_, kNoHandle);
  }
  return *this;
}

void Channel::close() {
  if (handle_ != kNoHandle) ::close(fd_of(handle_));
  handle_ = kNoHandle;
}

bool Channel::write_all(const void* data, size_t size) {
  const char* at = static_cast<const char*>(data);
  while (size > 0) {
    // send() where it is a socket (no SIGPIPE for a peer that is gone), write() on a pipe.
    ssize_t w = send(fd_of(handle_), at, size, MSG_NOSIGNAL);
    if (w < 0 && errno == ENOTSOCK) w = write_without_signal(fd_of(handle_), at, size);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && errno == EAGAIN) {  // a non-blocking descriptor handed to us: wait for room
      pollfd p{fd_of(handle_), POLLOUT, 0};
      poll(&p, 1, -1);
      continue;
    }
    if (w <= 0) return false;
    at += w;
    size -= static_cast<size_t>(w);
  }
  return true;
}

ChannelStatus Channel::read_some(void* data, size_t size, int timeout_ms, size_t* got) {
  *got = 0;
  if (handle_ == kNoHandle) return ChannelStatus::Failed;
  for (;;) {
    pollfd p{fd_of(handle_), POLLIN, 0};
    const int ready = poll(&p, 1, timeout_ms < 0 ? -1 : timeout_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return ChannelStatus::Failed;
    if (ready == 0) return ChannelStatus::TimedOut;
    const ssize_t r = read(fd_of(handle_), data, size);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0 && errno == EAGAIN) {
      if (timeout_ms == 0) return ChannelStatus::TimedOut;
      continue;
    }
    if (r < 0) return errno == ECONNRESET ? ChannelStatus::Closed : ChannelStatus::Failed;
    if (r == 0) return ChannelStatus::Closed;
    *got = static_cast<size_t>(r);
    return ChannelStatus::Ok;
  }
}

bool make_channel_pair(ChannelPair* pair, std::string* error) {
  int sv[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
    return refused("cannot make a socket pair", error);
  pair->ours = Channel(sv[0]);
  pair->theirs = Channel(sv[1]);
  return true;
}

bool make_pipe(ChannelPair* pair, std::string* error) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return refused("cannot make a pipe", error);
  pair->ours = Channel(fds[0]);
  pair->theirs = Channel(fds[1]);
  return true;
}

int wait_readable(Channel* const* channels, size_t count, int timeout_ms) {
  // On the stack: the render worker's calls look here in a spin loop, many times a frame.
  constexpr size_t kMost = 16;
  pollfd fds[kMost];
  int index[kMost];
  nfds_t open = 0;
  for (size_t i = 0; i < count && open < kMost; ++i)
    if (channels[i]->is_open()) {
      fds[open] = {fd_of(channels[i]->handle()), POLLIN, 0};
      index[open++] = static_cast<int>(i);
    }
  for (;;) {
    const int ready = poll(fds, open, timeout_ms < 0 ? -1 : timeout_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) return -1;
    for (nfds_t i = 0; i < open; ++i)
      if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) return index[i];
    return -1;
  }
}

}  // namespace fr
