#include "io/atomic_file.hpp"

#include "platform/interrupt.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace fr {
namespace {

// Temporary files being written now, for the signal handler: fixed slots, since the handler may
// only touch memory that is always valid and call async-signal-safe functions (unlink).
constexpr int kTempSlots = 16;
constexpr size_t kTempPathMax = 4096;
char g_temp_paths[kTempSlots][kTempPathMax];
// 0: free, 1: being filled, 2: holds a path the handler may remove.
std::atomic<int> g_temp_state[kTempSlots];

// A slot holding `path`, or -1 when all are taken (then a signal may leave this one file).
int register_temp(const std::string& path) {
  if (path.size() >= kTempPathMax) return -1;
  for (int i = 0; i < kTempSlots; ++i) {
    int expected = 0;
    if (!g_temp_state[i].compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_temp_paths[i], path.c_str(), path.size() + 1);
    g_temp_state[i] = 2;
    return i;
  }
  return -1;
}

void unregister_temp(int slot) {
  if (slot >= 0) g_temp_state[slot] = 0;
}

// The line the handler writes before the process ends (set_signal_note): two buffers, so that a
// note being written never is the one the handler reads.
constexpr size_t kNoteMax = 1024;
char g_notes[2][kNoteMax];
std::atomic<int> g_note_current{-1};

// The last words before an interrupt ends the process (platform/interrupt.hpp): the note, then
// no temporary file left.
void say_note_and_remove_temps() {
  const int note = g_note_current.load();
  if (note >= 0) {
    const ssize_t written = write(STDERR_FILENO, g_notes[note], strlen(g_notes[note]));
    (void)written;
  }
  remove_temp_files();
}

// Bits for temporary file names: not secret, only unlikely to repeat.
uint32_t random_bits() {
  static std::atomic<uint32_t> counter{0};
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  return static_cast<uint32_t>(now) * 2654435761u + counter.fetch_add(0x9e3779b9u);
}

// 0666 less the process's umask, read without changing it (umask(2) would, for a moment, for
// every thread).
mode_t new_file_mode() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("Umask:", 0) == 0)
      return 0666 & ~static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
  return 0644;
}

const char* kind_name(mode_t mode) {
  if (S_ISDIR(mode)) return "is a folder, not a file";
  if (S_ISBLK(mode)) return "is a block device (a disk), which fractalis never writes to";
  if (S_ISSOCK(mode)) return "is a socket";
  return nullptr;
}

bool write_all(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

std::string output_problem(const std::filesystem::path& path) {
  struct stat link {};
  if (lstat(path.c_str(), &link) != 0) return "";  // a new file
  struct stat target {};
  if (stat(path.c_str(), &target) != 0)
    return S_ISLNK(link.st_mode)
               ? "is a symlink to nothing (" + std::string(std::strerror(errno)) + ")"
               : std::string(std::strerror(errno));
  if (const char* problem = kind_name(target.st_mode))
    return S_ISLNK(link.st_mode) ? std::string("is a symlink to what ") + problem : problem;
  return "";
}

bool is_standard_output(const std::filesystem::path& path) {
  struct stat file {
  }, out{};
  return stat(path.c_str(), &file) == 0 && fstat(STDOUT_FILENO, &out) == 0 &&
         file.st_dev == out.st_dev && file.st_ino == out.st_ino;
}

std::unique_ptr<OutputFile> OutputFile::open(const std::filesystem::path& path,
                                             std::string* error) {
  if (const std::string problem = output_problem(path); !problem.empty()) {
    *error = "cannot write " + path.string() + ": it " + problem;
    return nullptr;
  }
  std::unique_ptr<OutputFile> out(new OutputFile());
  out->path_ = out->real_ = path;
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      // Written through: no temporary file, nothing replaced.
      out->fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      if (out->fd_ < 0) {
        *error = "cannot write " + path.string() + ": " + std::strerror(errno);
        return nullptr;
      }
      return out;
    }
    out->mode_ = st.st_mode & 07777;
    struct stat link {};
    if (lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
      std::error_code ec;
      out->real_ = std::filesystem::canonical(path, ec);  // the link's target is replaced
      if (ec) {
        *error = "cannot write " + path.string() + ": " + ec.message();
        return nullptr;
      }
    }
  } else {
    out->mode_ = new_file_mode();
  }
  const std::filesystem::path dir = out->real_.has_parent_path() ? out->real_.parent_path() : ".";
  // The temporary file's name is registered for the signal handler before the file exists: a
  // signal may be delivered to any thread, so blocking it in this one would not close the gap
  // between creating the file and registering it. (Removing a name not yet created is harmless;
  // the pid in the name keeps it from being another process's file.)
  int create_errno = 0;
  for (int attempt = 0; attempt < 100 && out->fd_ < 0; ++attempt) {
    char suffix[40];
    std::snprintf(suffix, sizeof suffix, ".%ld.%08x", static_cast<long>(getpid()),
                  static_cast<unsigned>(random_bits()));
    std::string hidden = out->real_.filename().string();  // appended: GCC 12's -Wrestrict
    hidden.insert(hidden.begin(), '.');                   // misfires on "." + string
    hidden += suffix;
    out->temp_ = (dir / hidden).string();
    out->slot_ = register_temp(out->temp_);
    out->fd_ = ::open(out->temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    create_errno = errno;
    if (out->fd_ < 0) {
      unregister_temp(out->slot_);
      out->slot_ = -1;
      if (create_errno != EEXIST) break;
    }
  }
  if (out->fd_ < 0) {
    *error = "cannot write " + path.string() + ": cannot create a temporary file in " +
             dir.string() + ": " + std::strerror(create_errno);
    out->temp_.clear();
    return nullptr;
  }
  return out;
}

bool OutputFile::write(std::string_view bytes, std::string* error) {
  if (write_all(fd_, bytes)) {
    position_ += bytes.size();
    return true;
  }
  *error = "cannot write " + path_.string() + ": write failed: " + std::strerror(errno);
  return false;
}

bool OutputFile::seek(uint64_t offset, std::string* error) {
  if (seekable() && lseek(fd_, static_cast<off_t>(offset), SEEK_SET) >= 0) {
    position_ = offset;
    return true;
  }
  *error = "cannot write " + path_.string() + ": " +
           (seekable() ? std::string("seek failed: ") + std::strerror(errno)
                       : std::string("this format must seek, and a pipe or device cannot"));
  return false;
}

bool OutputFile::commit(std::string* error) {
  auto fail = [&](const char* what) {
    *error = "cannot write " + path_.string() + ": " + what + ": " + std::strerror(errno);
    return false;
  };
  if (temp_.empty()) {  // written through
    const int fd = fd_;
    fd_ = -1;
    done_ = true;
    return close(fd) == 0 || fail("close failed");
  }
  if (fchmod(fd_, static_cast<mode_t>(mode_)) != 0) return fail("chmod failed");
  if (fsync(fd_) != 0) return fail("fsync failed");
  const int fd = fd_;
  fd_ = -1;
  if (close(fd) != 0) return fail("close failed");
  if (rename(temp_.c_str(), real_.c_str()) != 0) return fail("rename failed");
  unregister_temp(slot_);
  done_ = true;
  return true;
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) close(fd_);
  if (!done_ && !temp_.empty()) {
    unlink(temp_.c_str());
    unregister_temp(slot_);
  }
}

bool write_file_atomic(const std::filesystem::path& path, std::string_view bytes,
                       std::string* error) {
  auto out = OutputFile::open(path, error);
  return out && out->write(bytes, error) && out->commit(error);
}

void remove_temp_files() {
  for (int i = 0; i < kTempSlots; ++i)
    if (g_temp_state[i].load() == 2) unlink(g_temp_paths[i]);
}

void set_signal_note(std::string_view note) {
  if (note.empty()) {
    g_note_current = -1;
    return;
  }
  const int next = g_note_current.load() == 0 ? 1 : 0;
  const size_t n = std::min(note.size(), kNoteMax - 2);
  std::memcpy(g_notes[next], note.data(), n);
  g_notes[next][n] = '\n';
  g_notes[next][n + 1] = '\0';
  g_note_current = next;
}

void install_temp_file_cleanup() {
  on_termination_request(say_note_and_remove_temps);
}

}  // namespace fr
