// child_process.hpp — starting a helper process (a scene host, a test render) the one careful way.
//
// fractalis is multithreaded (spdlog, OpenCL, the watcher), so between fork and exec the child may
// only make async-signal-safe calls: everything is prepared before the fork. The child gets
// /dev/null for stdin and stdout, the descriptors it is given at the numbers it expects, no other
// descriptor of ours (a plugin must not inherit the window's or another plugin's), an empty
// signal mask (a mask blocked in one of our threads is inherited through fork), SIGKILL when
// fractalis dies, so that no helper outlives it, and our environment less an MPI launcher's
// variables (OMPI_*, PMIX_*, PMI_*): a helper of one rank is not a rank of the job.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace fr {

// Exit status of a child whose exec (or set-up before it) failed.
constexpr int kChildExecFailedStatus = 127;

struct ChildDescriptor {
  int ours;    // a descriptor of this process
  int theirs;  // the number it has in the child (3 and up)
};

// Starts argv[0] with `argv`. `stderr_fd`: the child's stderr (-1: /dev/null; 2: ours);
// `stdout_fd` likewise its stdout (-1: /dev/null). Returns the child's pid, or -1 with *error
// saying why.
pid_t start_child_process(const std::vector<std::string>& argv,
                          const std::vector<ChildDescriptor>& descriptors, int stderr_fd,
                          std::string* error, int stdout_fd = -1);

// How a child that waitpid reported with `status` ended: "crashed (SIGSEGV: Segmentation
// fault)", "exited with status 3", "could not be started (exec failed)".
std::string describe_child_exit(int status);

// A helper executable of fractalis (the scene host, the render worker): $ENV_VARIABLE when set,
// else beside the running executable, else in ../libexec/fractalis/ from it, else `build_path`
// (the build tree's). Empty when none of them exists.
std::filesystem::path helper_executable(const char* name, const char* env_variable,
                                        const char* build_path);

}  // namespace fr
