// atomic_file.hpp — writing an output file so that it appears whole or not at all, and never
// replaces what is not a plain file.
//
// What an output path may name, and what writing it does:
//   - nothing yet, or a regular file: the bytes go to a hidden temporary file beside it, which is
//     flushed and renamed over it. An existing file keeps its permission bits; a new one gets
//     0666 less the umask.
//   - a symlink to a regular file: the same, beside the link's target; the link stays a link.
//   - a character device or a FIFO (/dev/stdout piped on, /dev/null, a named pipe): the bytes are
//     written through to it; nothing is replaced.
//   - a folder, a block device, a socket, or a symlink to nothing: refused (output_problem says
//     why, so the CLI refuses it with exit code 2 before any work).
// A temporary file is removed when the write fails, and when SIGINT, SIGTERM or SIGHUP ends the
// process mid-write (install_temp_file_cleanup), so no hidden half-file is ever left behind.
#pragma once

#include "platform/files.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace fr {

// Why `path` cannot be an output file ("is a block device"), or "" when it can.
std::string output_problem(const std::filesystem::path& path);

// True when `path` is this process's standard output (/dev/stdout, /proc/self/fd/1, or the file
// or pipe stdout goes to): then a command's own report goes to stderr, not into the file.
bool is_standard_output(const std::filesystem::path& path);

// An output file written piece by piece (a poster's PNG, a band of rows at a time), with the
// same rules: the pieces go to the temporary file (or straight through to a FIFO or character
// device), and only commit() puts the file in place; destroyed without commit() — an error, an
// exception — it removes the temporary file.
class OutputFile {
 public:
  // Nullptr with *error (naming the path and why) when `path` cannot be written.
  static std::unique_ptr<OutputFile> open(const std::filesystem::path& path, std::string* error);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  bool write(std::string_view bytes, std::string* error);
  bool commit(std::string* error);  // flush to disk and rename into place

  // Formats that patch their header or index after the data (MP4, OpenEXR) need to move within
  // the file: possible for a temporary file, not for a pipe or a character device written
  // through. position() is the byte offset the next write goes to.
  bool seekable() const { return !temp_.empty(); }
  bool seek(uint64_t offset, std::string* error);
  uint64_t position() const { return position_; }

 private:
  OutputFile() = default;
  std::filesystem::path path_;  // as given, for messages
  std::filesystem::path real_;  // what the rename replaces (a symlink's target)
  std::string temp_;            // empty when writing through
  WritableFile file_;
  int slot_ = -1;
  unsigned mode_ = 0;
  uint64_t position_ = 0;
  bool done_ = false;
};

// Writes `bytes` to `path` as described above. On failure returns false, sets *error (naming the
// path and the reason) and leaves any existing file at `path` untouched.
bool write_file_atomic(const std::filesystem::path& path, std::string_view bytes,
                       std::string* error);

// Removes the temporary files of every write in progress (async-signal-safe: unlink only), for
// a process about to end abruptly (the watchdog's _exit).
void remove_temp_files();

// A line those handlers write to stderr before the process ends by a signal (what was in
// progress: an MPI job's rank 0 names the frames its ranks were rendering); empty: none. Only
// its first 1022 bytes are kept. Call from one thread.
void set_signal_note(std::string_view note);

// Installs handlers for SIGINT, SIGTERM and SIGHUP (where their action is the default) that
// remove the temporary files of writes in progress, then end the process by the same signal.
// Call once, early in main.
void install_temp_file_cleanup();

}  // namespace fr
