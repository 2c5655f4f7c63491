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

#include <string>
#include <vector>

namespace fr {

// Exit status of a child whose exec (or set-up before it) failed.
constexpr int kChildExecFailedStatus = 127;

struct ChildDescriptor {
  int ours;    // a descriptor of this process
  int theirs;  // the number it has in the child (3 and up)
};

// Starts argv[0] with `argv`. `stderr_fd`: the child's stderr (-1: /dev/null; 2: ours). Returns
// the child's pid, or -1 with *error saying why.
pid_t start_child_process(const std::vector<std::string>& argv,
                          const std::vector<ChildDescriptor>& descriptors, int stderr_fd,
                          std::string* error);

}  // namespace fr
