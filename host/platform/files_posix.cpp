#include "platform/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace fr {
namespace {

PathKind kind_of(mode_t mode) {
  if (S_ISREG(mode)) return PathKind::Regular;
  if (S_ISDIR(mode)) return PathKind::Folder;
  if (S_ISCHR(mode)) return PathKind::CharacterDevice;
  if (S_ISFIFO(mode)) return PathKind::Pipe;
  if (S_ISBLK(mode)) return PathKind::BlockDevice;
  if (S_ISSOCK(mode)) return PathKind::Socket;
  return PathKind::Other;
}

bool failed(std::string* error) {
  *error = std::strerror(errno);
  return false;
}

}  // namespace

PathInfo examine_path(const std::filesystem::path& path) {
  PathInfo info;
  struct stat link {};
  if (lstat(path.c_str(), &link) != 0) {
    // Nothing there, or a folder on the way that may not be searched: say which.
    if (errno != ENOENT && errno != ENOTDIR) info.error = std::strerror(errno);
    return info;
  }
  info.is_link = S_ISLNK(link.st_mode);
  struct stat target {};
  if (stat(path.c_str(), &target) != 0) {
    info.loops = errno == ELOOP;
    info.error = std::strerror(errno);  // a link to nothing, or a race with its removal
    return info;
  }
  info.kind = kind_of(target.st_mode);
  info.mode = target.st_mode & 07777;
  return info;
}

namespace {

// Why a file or folder with this status could be changed by a user other than us or root.
std::string foreign_writer(const struct stat& st, bool is_folder) {
  const uid_t me = geteuid();
  if (st.st_uid != me && st.st_uid != 0)
    return "owned by user " + std::to_string(st.st_uid) + ", not by you or root";
  // A sticky folder (like /tmp) lets others add entries but not replace or rename ours.
  if (is_folder && (st.st_mode & S_ISVTX)) return "";
  if (st.st_mode & S_IWOTH) return "writable by every user";
  if ((st.st_mode & S_IWGRP) && st.st_gid != getegid())
    return "writable by group " + std::to_string(st.st_gid);
  return "";
}

int64_t nanoseconds(const struct timespec& t) {
  return int64_t{t.tv_sec} * 1000000000 + t.tv_nsec;
}

}  // namespace

std::string others_who_can_write(const std::filesystem::path& path, bool is_folder) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return std::string("cannot stat: ") + std::strerror(errno);
  return foreign_writer(st, is_folder);
}

ReadableFile::~ReadableFile() {
  if (handle_ != kNone) ::close(static_cast<int>(handle_));
}

ReadableFile ReadableFile::open(const std::filesystem::path& path, std::string* error) {
  // O_NONBLOCK: a FIFO opens without waiting for a writer (fstat below then says what it is).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int err = errno;
    struct stat own {};
    if (err == ELOOP)
      *error = "a symlink loop";
    else if (err == ENOENT && lstat(path.c_str(), &own) == 0 && S_ISLNK(own.st_mode))
      *error = "a dangling symlink";
    else
      *error = std::string("cannot open: ") + std::strerror(err);
    return ReadableFile();
  }
  return adopt(fd, error);
}

std::optional<FileIdentity> identity_of(const std::filesystem::path& path, std::string* error) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    *error = std::string("cannot examine ") + path.string() + ": " + std::strerror(errno);
    return std::nullopt;
  }
  return FileIdentity{static_cast<uint64_t>(st.st_dev), static_cast<uint64_t>(st.st_ino),
                      static_cast<uint64_t>(st.st_size), nanoseconds(st.st_mtim),
                      nanoseconds(st.st_ctim)};
}

ReadableFile ReadableFile::adopt(intptr_t handle, std::string* error) {
  ReadableFile file;
  file.handle_ = handle;
  struct stat st {};
  if (fstat(static_cast<int>(handle), &st) != 0) {
    *error = std::string("cannot examine the open file: ") + std::strerror(errno);
    return ReadableFile();
  }
  file.kind_ = kind_of(st.st_mode);
  file.identity_ = {static_cast<uint64_t>(st.st_dev), static_cast<uint64_t>(st.st_ino),
                    static_cast<uint64_t>(st.st_size), nanoseconds(st.st_mtim),
                    nanoseconds(st.st_ctim)};
  return file;
}

std::string ReadableFile::others_who_can_write() const {
  struct stat st {};
  if (fstat(static_cast<int>(handle_), &st) != 0)
    return std::string("cannot stat: ") + std::strerror(errno);
  return foreign_writer(st, S_ISDIR(st.st_mode));
}

bool ReadableFile::read_all(uint64_t max_bytes, std::string* bytes, std::string* error) const {
  bytes->clear();
  char buffer[1 << 16];
  for (;;) {
    // pread: the position is not shared with a child process that was handed this descriptor.
    const ssize_t n =
        pread(static_cast<int>(handle_), buffer, sizeof buffer, static_cast<off_t>(bytes->size()));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      *error = std::string("cannot read: ") + std::strerror(errno);
      return false;
    }
    if (n == 0) return true;
    if (bytes->size() + static_cast<size_t>(n) > max_bytes) {
      *error = "more than " + std::to_string(max_bytes) + " bytes";
      return false;
    }
    bytes->append(buffer, static_cast<size_t>(n));
  }
}

bool is_standard_output_path(const std::filesystem::path& path) {
  struct stat file {
  }, out{};
  return stat(path.c_str(), &file) == 0 && fstat(STDOUT_FILENO, &out) == 0 &&
         file.st_dev == out.st_dev && file.st_ino == out.st_ino;
}

bool can_write_in(const std::filesystem::path& folder) {
  return access(folder.c_str(), W_OK) == 0;
}

unsigned new_file_mode() {
  // umask(2) would change it, for a moment, for every thread: /proc says it instead.
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("Umask:", 0) == 0)
      return 0666 & ~static_cast<unsigned>(std::strtoul(line.c_str() + 6, nullptr, 8));
  return 0644;
}

uint64_t current_process_id() {
  return static_cast<uint64_t>(getpid());
}

WritableFile::~WritableFile() {
  if (handle_ != kNone) ::close(static_cast<int>(handle_));
}

WritableFile::WritableFile(WritableFile&& other) noexcept : handle_(other.handle_) {
  other.handle_ = kNone;
}

WritableFile& WritableFile::operator=(WritableFile&& other) noexcept {
  if (this != &other) {
    if (handle_ != kNone) ::close(static_cast<int>(handle_));
    handle_ = other.handle_;
    other.handle_ = kNone;
  }
  return *this;
}

WritableFile WritableFile::create_new(const std::filesystem::path& path, bool* exists,
                                      std::string* error) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  *exists = fd < 0 && errno == EEXIST;
  if (fd < 0) failed(error);
  return WritableFile(fd);
}

WritableFile WritableFile::open_existing(const std::filesystem::path& path, std::string* error) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) failed(error);
  return WritableFile(fd);
}

bool WritableFile::write_all(std::string_view bytes, std::string* error) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(static_cast<int>(handle_), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return failed(error);
    done += static_cast<size_t>(n);
  }
  return true;
}

bool WritableFile::seek(uint64_t offset, std::string* error) {
  return lseek(static_cast<int>(handle_), static_cast<off_t>(offset), SEEK_SET) >= 0 ||
         failed(error);
}

bool WritableFile::set_mode(unsigned mode, std::string* error) {
  return fchmod(static_cast<int>(handle_), static_cast<mode_t>(mode)) == 0 || failed(error);
}

bool WritableFile::flush_to_disk(std::string* error) {
  return fsync(static_cast<int>(handle_)) == 0 || failed(error);
}

bool WritableFile::close(std::string* error) {
  const int fd = static_cast<int>(handle_);
  handle_ = kNone;
  return ::close(fd) == 0 || failed(error);
}

bool replace_file(const std::filesystem::path& from, const std::filesystem::path& to,
                  std::string* error) {
  return rename(from.c_str(), to.c_str()) == 0 || failed(error);
}

void remove_file_now(const char* path) {
  unlink(path);
}

void write_stderr_now(const char* text) {
  const ssize_t written = write(STDERR_FILENO, text, strlen(text));
  (void)written;
}

}  // namespace fr
