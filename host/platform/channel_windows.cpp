#include "platform/channel.hpp"

#include "platform/last_error_windows.hpp"

#include <windows.h>

#include <atomic>
#include <chrono>
#include <random>
#include <thread>
#include <utility>

namespace fr {
namespace {

HANDLE as_handle(NativeHandle h) {
  return reinterpret_cast<HANDLE>(h);
}

NativeHandle as_native(HANDLE h) {
  return reinterpret_cast<NativeHandle>(h);
}

bool refused(const char* what, std::string* error) {
  *error = std::string(what) + ": " + last_error_text();
  return false;
}

// An event for one kind of overlapped operation on a channel, made on first use.
HANDLE event_of(NativeHandle* slot) {
  if (*slot == kNoHandle) {
    const HANDLE e = CreateEventW(nullptr, TRUE, FALSE, nullptr);
    if (!e) return nullptr;
    *slot = as_native(e);
  }
  return as_handle(*slot);
}

// What is waiting in the pipe: > 0 bytes, 0 nothing yet, -1 the other end is gone, -2 an error.
long long bytes_waiting(NativeHandle h) {
  DWORD available = 0;
  if (PeekNamedPipe(as_handle(h), nullptr, 0, nullptr, &available, nullptr))
    return static_cast<long long>(available);
  const DWORD code = GetLastError();
  return code == ERROR_BROKEN_PIPE || code == ERROR_PIPE_NOT_CONNECTED || code == ERROR_NO_DATA
             ? -1
             : -2;
}

// A name nobody else can guess or have taken first (FILE_FLAG_FIRST_PIPE_INSTANCE refuses a
// name that exists), and the two handles on it: the server end, and a client end opened on it.
// `client_flags`: FILE_FLAG_OVERLAPPED for a client that is a Channel too; 0 for one that a child
// writes with plain WriteFile (its stdout: the C runtime knows nothing of overlapped handles).
bool make_named_pipe(DWORD server_access, DWORD client_access, DWORD client_flags, HANDLE* server,
                     HANDLE* client, std::string* error) {
  static std::atomic<unsigned> serial{0};
  std::random_device random;
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::wstring name = L"\\\\.\\pipe\\fractalis-" + std::to_wstring(GetCurrentProcessId()) +
                              L"-" + std::to_wstring(serial++) + L"-" + std::to_wstring(random()) +
                              std::to_wstring(random());
    *server = CreateNamedPipeW(
        name.c_str(), server_access | FILE_FLAG_OVERLAPPED | FILE_FLAG_FIRST_PIPE_INSTANCE,
        PIPE_TYPE_BYTE | PIPE_READMODE_BYTE | PIPE_WAIT | PIPE_REJECT_REMOTE_CLIENTS, 1, 1 << 16,
        1 << 16, 0, nullptr);
    if (*server == INVALID_HANDLE_VALUE) {
      if (GetLastError() == ERROR_ACCESS_DENIED) continue;  // the name was taken
      return refused("cannot make a named pipe", error);
    }
    *client =
        CreateFileW(name.c_str(), client_access, 0, nullptr, OPEN_EXISTING, client_flags, nullptr);
    if (*client == INVALID_HANDLE_VALUE) {
      refused("cannot open the named pipe", error);
      CloseHandle(*server);
      return false;
    }
    // The client is there already: ConnectNamedPipe says so, or returns at once.
    OVERLAPPED connect{};
    connect.hEvent = CreateEventW(nullptr, TRUE, FALSE, nullptr);
    if (!ConnectNamedPipe(*server, &connect)) {
      const DWORD code = GetLastError();
      DWORD ignored = 0;
      if (code == ERROR_IO_PENDING) GetOverlappedResult(*server, &connect, &ignored, TRUE);
    }
    if (connect.hEvent) CloseHandle(connect.hEvent);
    return true;
  }
  *error = "cannot make a named pipe: every name tried was taken";
  return false;
}

}  // namespace

Channel::Channel(NativeHandle adopted) : handle_(adopted) {}

Channel::~Channel() {
  close();
}

Channel::Channel(Channel&& other) noexcept
    : handle_(std::exchange(other.handle_, kNoHandle)),
      read_event_(std::exchange(other.read_event_, kNoHandle)),
      write_event_(std::exchange(other.write_event_, kNoHandle)) {}

Channel& Channel::operator=(Channel&& other) noexcept {
  if (this != &other) {
    close();
    handle_ = std::exchange(other.handle_, kNoHandle);
    read_event_ = std::exchange(other.read_event_, kNoHandle);
    write_event_ = std::exchange(other.write_event_, kNoHandle);
  }
  return *this;
}

void Channel::close() {
  for (NativeHandle* h : {&handle_, &read_event_, &write_event_}) {
    if (*h != kNoHandle) CloseHandle(as_handle(*h));
    *h = kNoHandle;
  }
}

bool Channel::write_all(const void* data, size_t size) {
  const char* at = static_cast<const char*>(data);
  const HANDLE event = event_of(&write_event_);
  if (!event) return false;
  while (size > 0) {
    OVERLAPPED o{};
    o.hEvent = event;
    const DWORD chunk = static_cast<DWORD>(size < (1u << 30) ? size : (1u << 30));
    DWORD written = 0;
    if (!WriteFile(as_handle(handle_), at, chunk, nullptr, &o) &&
        GetLastError() != ERROR_IO_PENDING)
      return false;
    if (!GetOverlappedResult(as_handle(handle_), &o, &written, TRUE) || written == 0) return false;
    at += written;
    size -= written;
  }
  return true;
}

ChannelStatus Channel::read_some(void* data, size_t size, int timeout_ms, size_t* got) {
  *got = 0;
  if (handle_ == kNoHandle) return ChannelStatus::Failed;
  if (timeout_ms == 0) {  // only a look: read just what is there, so the read cannot wait
    const long long waiting = bytes_waiting(handle_);
    if (waiting == -1) return ChannelStatus::Closed;
    if (waiting < 0) return ChannelStatus::Failed;
    if (waiting == 0) return ChannelStatus::TimedOut;
    if (static_cast<unsigned long long>(waiting) < size) size = static_cast<size_t>(waiting);
  }
  const HANDLE event = event_of(&read_event_);
  if (!event) return ChannelStatus::Failed;
  OVERLAPPED o{};
  o.hEvent = event;
  const DWORD want = static_cast<DWORD>(size < (1u << 30) ? size : (1u << 30));
  DWORD read = 0;
  if (!ReadFile(as_handle(handle_), data, want, nullptr, &o)) {
    const DWORD code = GetLastError();
    if (code == ERROR_BROKEN_PIPE || code == ERROR_PIPE_NOT_CONNECTED) return ChannelStatus::Closed;
    if (code != ERROR_IO_PENDING) return ChannelStatus::Failed;
    const DWORD wait = WaitForSingleObject(event, timeout_ms < 0 ? INFINITE : DWORD(timeout_ms));
    if (wait == WAIT_TIMEOUT) {
      CancelIoEx(as_handle(handle_), &o);
      // The read may still have finished meanwhile: then its bytes count.
      if (!GetOverlappedResult(as_handle(handle_), &o, &read, TRUE) || read == 0)
        return ChannelStatus::TimedOut;
      *got = read;
      return ChannelStatus::Ok;
    }
  }
  if (!GetOverlappedResult(as_handle(handle_), &o, &read, TRUE)) {
    const DWORD code = GetLastError();
    return code == ERROR_BROKEN_PIPE || code == ERROR_PIPE_NOT_CONNECTED ? ChannelStatus::Closed
                                                                         : ChannelStatus::Failed;
  }
  if (read == 0) return ChannelStatus::Closed;
  *got = read;
  return ChannelStatus::Ok;
}

bool make_channel_pair(ChannelPair* pair, std::string* error) {
  HANDLE server = nullptr, client = nullptr;
  if (!make_named_pipe(PIPE_ACCESS_DUPLEX, GENERIC_READ | GENERIC_WRITE, FILE_FLAG_OVERLAPPED,
                       &server, &client, error))
    return false;
  pair->ours = Channel(as_native(server));
  pair->theirs = Channel(as_native(client));
  return true;
}

bool make_pipe(ChannelPair* pair, std::string* error) {
  HANDLE server = nullptr, client = nullptr;
  if (!make_named_pipe(PIPE_ACCESS_INBOUND, GENERIC_WRITE, 0, &server, &client, error))
    return false;
  pair->ours = Channel(as_native(server));
  pair->theirs = Channel(as_native(client));
  return true;
}

// A pipe has nothing to wait on for "readable" short of starting a read, so this looks with
// PeekNamedPipe: for the first 200 microseconds without pause (an answer usually comes that
// fast), then every millisecond.
int wait_readable(Channel* const* channels, size_t count, int timeout_ms) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  for (;;) {
    for (size_t i = 0; i < count && i < 16; ++i)  // as on Linux: the first 16
      if (channels[i]->is_open() && bytes_waiting(channels[i]->handle()) != 0)
        return static_cast<int>(i);
    const auto waited = Clock::now() - start;
    if (timeout_ms >= 0 && waited >= std::chrono::milliseconds(timeout_ms)) return -1;
    if (waited < std::chrono::microseconds(200))
      std::this_thread::yield();
    else
      Sleep(1);
  }
}

}  // namespace fr
