#include "platform/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>

extern char** environ;

namespace fr {
namespace {

// The child's numbers for the handles it is given: 3, 4, ... in ChildSpec::handles' order.
constexpr int kFirstChildHandle = 3;
constexpr size_t kMaxChildHandles = 16;

// A helper is never a rank of the MPI job its parent may belong to: with the launcher's
// variables it would start MPI and join the job as a rank the launcher never started.
bool is_mpi_launcher_variable(const char* entry) {
  for (const char* prefix : {"OMPI_", "PMIX_", "PMI_"})
    if (std::strncmp(entry, prefix, std::strlen(prefix)) == 0) return true;
  return false;
}

std::string describe_wait_status(int status) {
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

}  // namespace

void end_at_once_on_crash() {}

std::string handle_in_child(size_t index, NativeHandle) {
  return std::to_string(kFirstChildHandle + static_cast<int>(index));
}

NativeHandle handle_from_argument(const char* text) {
  char* end = nullptr;
  errno = 0;
  const long fd = std::strtol(text ? text : "", &end, 10);
  if (!text || end == text || *end != '\0' || errno != 0 || fd < 0 || fd > 1 << 20)
    return kNoHandle;
  return static_cast<NativeHandle>(fd);
}

NativeHandle own_stderr() {
  return 2;
}

std::unique_ptr<ChildProcess> ChildProcess::start(const ChildSpec& spec, std::string* error) {
  if (spec.program.empty()) {
    *error = "no program to start";
    return nullptr;
  }
  if (spec.handles.size() > kMaxChildHandles) {
    *error = "too many handles for a child";
    return nullptr;
  }
  const std::string program = spec.program.string();
  std::vector<const char*> args{program.c_str()};
  for (const auto& a : spec.arguments) args.push_back(a.c_str());
  args.push_back(nullptr);
  std::vector<char*> environment;  // built before fork: the child may not allocate
  for (char** e = environ; *e; ++e)
    if (!is_mpi_launcher_variable(*e)) environment.push_back(*e);
  environment.push_back(nullptr);
  const int count = static_cast<int>(spec.handles.size());
  const int first_free = kFirstChildHandle + count;
  // Every handle is first copied above all the target numbers, so that placing one cannot
  // overwrite another that is still to be placed.
  const int above = first_free + count + 3;
  int given[kMaxChildHandles];
  for (int i = 0; i < count; ++i) given[i] = static_cast<int>(spec.handles[i]);
  const int stderr_fd = static_cast<int>(spec.stderr_to);
  const int stdout_fd = static_cast<int>(spec.stdout_to);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    *error = std::string("fork failed: ") + std::strerror(errno);
    return nullptr;
  }
  if (pid == 0) {
    // The child: async-signal-safe calls only, until exec.
    int copies[kMaxChildHandles];
    for (int i = 0; i < count; ++i)
      if ((copies[i] = fcntl(given[i], F_DUPFD, above)) < 0) _exit(kChildExecFailedStatus);
    const int err_copy = stderr_fd >= 0 ? fcntl(stderr_fd, F_DUPFD, above) : -1;
    const int out_copy = stdout_fd >= 0 ? fcntl(stdout_fd, F_DUPFD, above) : -1;
    for (int i = 0; i < count; ++i)
      if (dup2(copies[i], kFirstChildHandle + i) < 0) _exit(kChildExecFailedStatus);
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
  std::unique_ptr<ChildProcess> child(new ChildProcess());
  child->id_ = pid;
  return child;
}

ChildProcess::~ChildProcess() {
  if (!ended_) kill();
}

bool ChildProcess::wait(int timeout_ms) {
  if (ended_) return true;
  const pid_t pid = static_cast<pid_t>(id_);
  int status = 0;
  pid_t r = 0;
  if (timeout_ms < 0) {
    while ((r = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
    }
  } else {
    // Polled: a child that ends within the time is seen within 2 ms of it.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
    while ((r = waitpid(pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (r == 0) return false;
  }
  ended_ = true;
  if (r != pid) {
    how_ = "ended (its status could not be read)";
    return true;
  }
  how_ = describe_wait_status(status);
  if (WIFEXITED(status)) exit_status_ = WEXITSTATUS(status);
  return true;
}

void ChildProcess::kill() {
  if (ended_) return;
  ::kill(static_cast<pid_t>(id_), SIGKILL);
  wait(-1);
  how_ = "was killed";
  exit_status_ = -1;
}

uint64_t ChildProcess::resident_bytes() const {
  if (ended_) return 0;
  std::ifstream statm("/proc/" + std::to_string(id_) + "/statm");
  uint64_t size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return 0;
  return resident_pages * static_cast<uint64_t>(sysconf(_SC_PAGESIZE));
}

std::string executable_file_name(const std::string& name) {
  return name;
}

char path_list_separator() {
  return ':';
}

bool is_executable_file(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) && access(path.c_str(), X_OK) == 0;
}

void limit_written_file_size(uint64_t bytes) {
  const rlimit limit{bytes, bytes};
  setrlimit(RLIMIT_FSIZE, &limit);
}

}  // namespace fr
