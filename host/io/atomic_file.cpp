#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

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

void remove_temps_and_die(int sig) {
  for (int i = 0; i < kTempSlots; ++i)
    if (g_temp_state[i].load() == 2) unlink(g_temp_paths[i]);
  signal(sig, SIG_DFL);
  raise(sig);
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

// Writes through to a character device or FIFO: no temporary file, nothing replaced.
bool write_through(const std::filesystem::path& path, std::string_view bytes, std::string* error) {
  const int fd = open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    *error = "cannot write " + path.string() + ": " + std::strerror(errno);
    return false;
  }
  const bool ok = write_all(fd, bytes);
  const int write_errno = errno;
  if (close(fd) != 0 || !ok) {
    *error = "cannot write " + path.string() + ": " + std::strerror(ok ? errno : write_errno);
    return false;
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

bool write_file_atomic(const std::filesystem::path& path, std::string_view bytes,
                       std::string* error) {
  if (const std::string problem = output_problem(path); !problem.empty()) {
    *error = "cannot write " + path.string() + ": it " + problem;
    return false;
  }
  std::filesystem::path real = path;
  mode_t mode = 0;
  struct stat st {};
  if (stat(path.c_str(), &st) == 0) {
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return write_through(path, bytes, error);
    mode = st.st_mode & 07777;
    struct stat link {};
    if (lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
      std::error_code ec;
      real = std::filesystem::canonical(path, ec);  // the link's target is replaced, not the link
      if (ec) {
        *error = "cannot write " + path.string() + ": " + ec.message();
        return false;
      }
    }
  } else {
    mode = new_file_mode();
  }
  const std::filesystem::path dir = real.has_parent_path() ? real.parent_path() : ".";
  // The temporary file's name is registered for the signal handler before the file exists: a
  // signal may be delivered to any thread, so blocking it in this one would not close the gap
  // between creating the file and registering it. (Removing a name not yet created is harmless;
  // the pid in the name keeps it from being another process's file.)
  std::string tmpl;
  int fd = -1, slot = -1, create_errno = 0;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    char suffix[40];
    std::snprintf(suffix, sizeof suffix, ".%ld.%08x", static_cast<long>(getpid()),
                  static_cast<unsigned>(random_bits()));
    std::string hidden = real.filename().string();  // built by appending: GCC 12's -Wrestrict
    hidden.insert(hidden.begin(), '.');             // misfires on "." + string
    hidden += suffix;
    tmpl = (dir / hidden).string();
    slot = register_temp(tmpl);
    fd = open(tmpl.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    create_errno = errno;
    if (fd < 0) unregister_temp(slot);
    if (fd < 0 && create_errno != EEXIST) break;
  }
  if (fd < 0) {
    *error = "cannot write " + path.string() + ": cannot create a temporary file in " +
             dir.string() + ": " + std::strerror(create_errno);
    return false;
  }
  auto fail = [&](const char* what) {
    *error = "cannot write " + path.string() + ": " + what + ": " + std::strerror(errno);
    close(fd);
    unlink(tmpl.c_str());
    unregister_temp(slot);
    return false;
  };
  if (!write_all(fd, bytes)) return fail("write failed");
  if (fchmod(fd, mode) != 0) return fail("chmod failed");
  if (fsync(fd) != 0) return fail("fsync failed");
  if (close(fd) != 0) {
    *error = "cannot write " + path.string() + ": close failed: " + std::strerror(errno);
    unlink(tmpl.c_str());
    unregister_temp(slot);
    return false;
  }
  if (rename(tmpl.c_str(), real.c_str()) != 0) {
    *error = "cannot write " + path.string() + ": rename failed: " + std::strerror(errno);
    unlink(tmpl.c_str());
    unregister_temp(slot);
    return false;
  }
  unregister_temp(slot);
  return true;
}

void install_temp_file_cleanup() {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;  // e.g. nohup
    struct sigaction sa {};
    sa.sa_handler = remove_temps_and_die;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace fr
