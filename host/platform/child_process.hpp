// child_process.hpp — starting a helper process (a scene host, the render worker, a test
// render) the one careful way, and ending it.
//
// The child gets the null device for stdin, the handles it is given (each under the name
// handle_in_child says, which its command line passes on) and no other handle of ours: a
// plugin must not inherit the window's or another plugin's. (Windows: the handles are duplicated
// into the suspended child rather than inherited, and their values come on its stdin.) It dies with
// fractalis, so that no helper outlives it (Linux: PR_SET_PDEATHSIG; Windows: a job object that
// kills its processes when fractalis's handle to it closes). Its environment is ours less an MPI
// launcher's variables (OMPI_*, PMIX_*, PMI_*): a helper of one rank is not a rank of the job.
//
// Linux: fractalis is multithreaded (spdlog, OpenCL, the watcher), so between fork and exec the
// child makes only async-signal-safe calls; everything is prepared before the fork, and the
// child starts with an empty signal mask (a mask blocked in one of our threads is inherited).
// Windows: CreateProcessW with an explicit list of the handles to inherit.
#pragma once

#include "platform/channel.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fr {

struct ChildSpec {
  std::filesystem::path program;
  std::vector<std::string> arguments;  // after the program's name, UTF-8
  std::vector<NativeHandle> handles;   // given to the child; still owned by the caller
  NativeHandle stdout_to = kNoHandle;  // the child's stdout: kNoHandle for the null device
  NativeHandle stderr_to = kNoHandle;  // and stderr; own_stderr() for ours
};

// What the index-th of ChildSpec::handles is called in the child, as text for its command line
// (Linux: the descriptor's number; Windows: "#index"); the child turns it back with
// handle_from_argument.
std::string handle_in_child(size_t index, NativeHandle ours);
// kNoHandle when `text` names no handle.
NativeHandle handle_from_argument(const char* text);
// This process's stderr, to pass on as ChildSpec::stderr_to.
NativeHandle own_stderr();

class ChildProcess {
 public:
  // Starts `spec`; null with *error when it could not be started.
  static std::unique_ptr<ChildProcess> start(const ChildSpec& spec, std::string* error);
  ~ChildProcess();  // a child still running is killed; either way it is reaped
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // Waits at most `timeout_ms` (negative: for ever) for the child to end; true once it has.
  bool wait(int timeout_ms);
  // Ends it now (SIGKILL; TerminateProcess) and reaps it.
  void kill();
  bool ended() const { return ended_; }
  // How it ended, once ended(): "exited with status 3", "crashed (SIGSEGV: Segmentation fault)",
  // "crashed (access violation)", "was killed", "could not be started (exec failed)".
  const std::string& how_it_ended() const { return how_; }
  // Its exit status when it exited by itself, else -1.
  int exit_status() const { return exit_status_; }
  // Its process id, for messages.
  int64_t id() const { return id_; }
  // Memory it holds now (resident on Linux, the working set on Windows); 0 when unknown.
  uint64_t resident_bytes() const;

 private:
  ChildProcess() = default;
  int64_t id_ = -1;
  NativeHandle process_ = kNoHandle;  // Windows: the process's handle
  bool ended_ = false;
  int exit_status_ = -1;
  std::string how_;
};

// The file name of program `name` on this system: `name` on Linux, `name`.exe on Windows.
std::string executable_file_name(const std::string& name);
// What separates the folders of the PATH: ':' on Linux, ';' on Windows.
char path_list_separator();
// Whether `path` is a program this process may start (Linux: a file it may execute; Windows: a
// file).
bool is_executable_file(const std::filesystem::path& path);

// Called first thing by a helper (the scene host, the render worker), which runs other people's
// code: a crash ends it at once with the fault as its status, for fractalis to report. Windows:
// an unhandled exception no longer waits for Windows' error reporting or a debugger (Wine starts
// winedbg, which takes longer than a call's time limit: a crash read as a hang). Linux: nothing
// to do, a fatal signal's default already does that.
void end_at_once_on_crash();

// Exit status of a Linux child whose exec (or the set-up before it) failed.
constexpr int kChildExecFailedStatus = 127;

// Limits the size of every file this process writes, where the system can (Linux:
// RLIMIT_FSIZE, past which a write ends the process with SIGXFSZ; Windows: nothing).
void limit_written_file_size(uint64_t bytes);

}  // namespace fr
