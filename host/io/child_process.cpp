#include "io/child_process.hpp"

#include "platform/user_folders.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace fr {
namespace {

// A helper is never a rank of the MPI job its parent may belong to: with the launcher's
// variables it would start MPI and join the job as a rank the launcher never started.
bool is_mpi_launcher_variable(const char* entry) {
  for (const char* prefix : {"OMPI_", "PMIX_", "PMI_"})
    if (std::strncmp(entry, prefix, std::strlen(prefix)) == 0) return true;
  return false;
}

}  // namespace

pid_t start_child_process(const std::vector<std::string>& argv,
                          const std::vector<ChildDescriptor>& descriptors, int stderr_fd,
                          std::string* error, int stdout_fd) {
  if (argv.empty()) {
    *error = "no program to start";
    return -1;
  }
  std::vector<const char*> args;
  for (const auto& a : argv) args.push_back(a.c_str());
  args.push_back(nullptr);
  std::vector<char*> environment;  // built before fork: the child may not allocate
  for (char** e = environ; *e; ++e)
    if (!is_mpi_launcher_variable(*e)) environment.push_back(*e);
  environment.push_back(nullptr);
  int first_free = 3;
  for (const ChildDescriptor& d : descriptors) first_free = std::max(first_free, d.theirs + 1);
  // Every descriptor is first copied above all the target numbers, so that placing one cannot
  // overwrite another that is still to be placed.
  const int above = first_free + static_cast<int>(descriptors.size()) + 3;
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    *error = std::string("fork failed: ") + std::strerror(errno);
    return -1;
  }
  if (pid > 0) return pid;

  // The child: async-signal-safe calls only, until exec.
  int copies[16];
  const size_t count = descriptors.size() < 16 ? descriptors.size() : 16;
  for (size_t i = 0; i < count; ++i)
    if ((copies[i] = fcntl(descriptors[i].ours, F_DUPFD, above)) < 0) _exit(kChildExecFailedStatus);
  const int err_copy = stderr_fd >= 0 ? fcntl(stderr_fd, F_DUPFD, above) : -1;
  const int out_copy = stdout_fd >= 0 ? fcntl(stdout_fd, F_DUPFD, above) : -1;
  for (size_t i = 0; i < count; ++i)
    if (dup2(copies[i], descriptors[i].theirs) < 0) _exit(kChildExecFailedStatus);
  const int null_fd = open("/dev/null", O_RDWR);
  if (null_fd < 0) _exit(kChildExecFailedStatus);
  dup2(null_fd, 0);
  dup2(out_copy >= 0 ? out_copy : null_fd, 1);
  dup2(err_copy >= 0 ? err_copy : null_fd, 2);
  close_range(static_cast<unsigned>(first_free), ~0U, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(kChildExecFailedStatus);  // fractalis died before the prctl
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  execve(args[0], const_cast<char* const*>(args.data()), environment.data());
  _exit(kChildExecFailedStatus);
}

std::string describe_child_exit(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* abbrev = sigabbrev_np(sig);
    const char* text = strsignal(sig);
    return std::string("crashed (SIG") + (abbrev ? abbrev : std::to_string(sig).c_str()) + ": " +
           (text ? text : "signal") + ")";
  }
  if (WIFEXITED(status)) {
    if (WEXITSTATUS(status) == kChildExecFailedStatus) return "could not be started (exec failed)";
    return "exited with status " + std::to_string(WEXITSTATUS(status));
  }
  return "ended";
}

std::filesystem::path helper_executable(const char* name, const char* env_variable,
                                        const char* build_path) {
  if (const char* env = std::getenv(env_variable); env && *env) return env;
  const std::filesystem::path self = executable_path();
  std::vector<std::filesystem::path> candidates;
  if (!self.empty()) {
    candidates.push_back(self.parent_path() / name);
    candidates.push_back(self.parent_path().parent_path() / "libexec" / "fractalis" / name);
  }
  candidates.emplace_back(build_path);
  for (const auto& c : candidates)
    if (access(c.c_str(), X_OK) == 0) return c;
  return {};
}

}  // namespace fr
