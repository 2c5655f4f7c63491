// files.hpp — files as the system sees them: what a path names and who else could change it, a
// file opened for reading (plugins: plugin/plugin_files.hpp), a file opened for writing, and
// putting one file in another's place in one step (io/atomic_file.hpp builds its output files
// on these).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace fr {

enum class PathKind {
  Missing,  // nothing there (or, through a link, nothing at its end)
  Regular,  // a plain file
  Folder,
  CharacterDevice,  // /dev/null, a terminal; on Windows NUL and CON
  Pipe,             // a FIFO (POSIX) or a named pipe
  BlockDevice,      // a disk
  Socket,
  Other,
};

struct PathInfo {
  PathKind kind = PathKind::Missing;  // of what the path names, symbolic links followed
  bool is_link = false;               // the path itself is a symbolic link (or a reparse point)
  bool loops = false;                 // its links lead round in a circle (then kind is Missing)
  unsigned mode = 0;                  // permission bits (POSIX); 0 on Windows
  // Why what it names could not be examined: the path exists but leads nowhere (a link to
  // nothing), or looking failed for another reason than its absence (no permission). Empty for
  // a path that is simply not there.
  std::string error;
};
PathInfo examine_path(const std::filesystem::path& path);

// What a kind of path is, in words: "a regular file", "a directory", "a FIFO", "a socket"...
// (A pipe is "a FIFO" on both systems: on Windows only \\.\pipe\ names are pipes, which no
// folder holds.)
inline std::string describe(PathKind kind) {
  switch (kind) {
    case PathKind::Missing:
      return "nothing";
    case PathKind::Regular:
      return "a regular file";
    case PathKind::Folder:
      return "a directory";
    case PathKind::CharacterDevice:
      return "a character device";
    case PathKind::Pipe:
      return "a FIFO";
    case PathKind::BlockDevice:
      return "a block device";
    case PathKind::Socket:
      return "a socket";
    case PathKind::Other:
      break;
  }
  return "not a regular file";
}

// Why a user other than this one (or the system's administrator) could change the file or
// folder `path` names, or "" when none could: "owned by user 1001, not by you or root",
// "writable by every user", "writable by group 27" (POSIX: the owner and the permission bits; a
// sticky folder such as /tmp, where others may add entries but not replace ours, is not
// refused). Windows: the owner (not this user, the Administrators or the system) and the
// access control list's write rights given to Everyone, Users, Authenticated Users or Guests.
// An error reading it is a reason too.
std::string others_who_can_write(const std::filesystem::path& path, bool is_folder);

// The identity of a file's contents as the file system sees it: a rebuilt file differs in at
// least one of these. POSIX: st_dev, st_ino, st_size, st_mtim, st_ctim; Windows: the volume's
// serial number, the file index, the size, the last write and change times.
struct FileIdentity {
  uint64_t device = 0;
  uint64_t inode = 0;
  uint64_t size_bytes = 0;
  int64_t mtime_ns = 0;
  int64_t ctime_ns = 0;
  bool operator==(const FileIdentity&) const = default;
};

// The identity of the file at `path` without opening it (symbolic links followed), for a watcher
// that must not hold the file open: POSIX as above; Windows the size, the last write time and
// (in ctime_ns) the creation time at the file system's 100 ns (std::filesystem's last_write_time
// has whole seconds there: two builds of one size in one second looked the same). Nothing on
// failure, with *error set.
std::optional<FileIdentity> identity_of(const std::filesystem::path& path, std::string* error);

// A file open for reading. Opening never blocks (a FIFO opens without waiting for a writer, and
// kind() says what it is) and never makes a terminal this process's; the handle is not inherited
// by child processes unless handed to one (child_process.hpp). Move-only; closed when destroyed.
class ReadableFile {
 public:
  ReadableFile() = default;
  ~ReadableFile();  // closes it (files_posix.cpp, files_windows.cpp)
  ReadableFile(ReadableFile&& other) noexcept
      : handle_(std::exchange(other.handle_, kNone)),
        kind_(other.kind_),
        identity_(other.identity_) {}
  ReadableFile& operator=(ReadableFile&& other) noexcept {
    if (this != &other) {
      ReadableFile previous(std::move(*this));  // closed at the end of this call
      handle_ = std::exchange(other.handle_, kNone);
      kind_ = other.kind_;
      identity_ = other.identity_;
    }
    return *this;
  }

  // On failure *error is "a symlink loop", "a dangling symlink" or "cannot open: " and why.
  static ReadableFile open(const std::filesystem::path& path, std::string* error);
  // Takes over a handle open for reading (one a parent process handed over); invalid, with
  // *error, when the system cannot say what it is (the handle is closed then).
  static ReadableFile adopt(intptr_t handle, std::string* error);

  bool valid() const { return handle_ != kNone; }
  // What is open (not what the path names now: it may have been replaced since).
  PathKind kind() const { return kind_; }
  const FileIdentity& identity() const { return identity_; }
  // As others_who_can_write, for the file that is open.
  std::string others_who_can_write() const;
  // Every byte from the start; false (and *error) past max_bytes or when reading fails.
  bool read_all(uint64_t max_bytes, std::string* bytes, std::string* error) const;
  // A descriptor or a HANDLE, for handing to a child process.
  intptr_t handle() const { return handle_; }

 private:
  static constexpr intptr_t kNone = -1;
  intptr_t handle_ = kNone;
  PathKind kind_ = PathKind::Missing;
  FileIdentity identity_;
};

// Whether `path` is this process's standard output (/dev/stdout, the file or pipe it goes to).
bool is_standard_output_path(const std::filesystem::path& path);

// Whether this process may create files in `folder`.
bool can_write_in(const std::filesystem::path& folder);

// Permission bits a new file gets: 0666 less the umask (read without changing it); 0 on Windows.
unsigned new_file_mode();

// This process's id (for names no other process of fractalis uses at the same time).
uint64_t current_process_id();

// A file open for writing. Move-only; closed when destroyed. Errors say what the system said.
class WritableFile {
 public:
  WritableFile() = default;
  ~WritableFile();
  WritableFile(WritableFile&& other) noexcept;
  WritableFile& operator=(WritableFile&& other) noexcept;

  // A new file, never an existing one (*exists set when that is why it failed).
  static WritableFile create_new(const std::filesystem::path& path, bool* exists,
                                 std::string* error);
  // An existing device or pipe, written through.
  static WritableFile open_existing(const std::filesystem::path& path, std::string* error);

  bool valid() const { return handle_ != kNone; }
  bool write_all(std::string_view bytes, std::string* error);
  bool seek(uint64_t offset, std::string* error);
  bool set_mode(unsigned mode, std::string* error);  // nothing to do on Windows
  bool flush_to_disk(std::string* error);
  bool close(std::string* error);

 private:
  static constexpr intptr_t kNone = -1;
  explicit WritableFile(intptr_t handle) : handle_(handle) {}
  intptr_t handle_ = kNone;  // a descriptor, or a HANDLE
};

// Puts `from` in the place of `to` (replacing it) in one step on the same volume.
bool replace_file(const std::filesystem::path& from, const std::filesystem::path& to,
                  std::string* error);

// For a process about to end abruptly (platform/interrupt.hpp's last words): remove a file and
// write to stderr with calls a signal handler may make, no allocation.
void remove_file_now(const char* path);
void write_stderr_now(const char* text);

}  // namespace fr
