// files.hpp — files as the system sees them: what a path names, a file opened for writing, and
// putting one file in another's place in one step (io/atomic_file.hpp builds its output files
// on these).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

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
  unsigned mode = 0;                  // permission bits (POSIX); 0 on Windows
  // Why what it names could not be examined, when the path exists (a link to nothing: why not).
  std::string error;
};
PathInfo examine_path(const std::filesystem::path& path);

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
