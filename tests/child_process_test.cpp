// The one launcher of helper processes (io/child_process.hpp), checked by looking at the child
// in /proc once it has exec'd: it has exactly stdin and stdout on /dev/null, the stderr it was
// given, the descriptors it was given at their numbers, and none of ours (not even one opened
// without close-on-exec), and an empty signal mask although ours blocks signals.
#include "io/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>

namespace fr {
namespace {

std::string link_of(const std::string& path) {
  std::error_code ec;
  return std::filesystem::read_symlink(path, ec).string();
}

// Waits until `pid` runs `program` (exec done), at most 5 s.
bool wait_for_exec(pid_t pid, const std::string& program) {
  const std::string exe = "/proc/" + std::to_string(pid) + "/exe";
  for (int i = 0; i < 500; ++i) {
    if (link_of(exe) == program) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(ChildProcess, GetsOnlyItsDescriptorsAndAnEmptySignalMask) {
  const std::string sleep_program = std::filesystem::canonical("/bin/sleep").string();
  // Open without close-on-exec, as a careless library might: the child must not inherit it.
  const int leaked = open("/dev/null", O_RDONLY);
  ASSERT_GE(leaked, 3);
  int given[2], err[2];
  ASSERT_EQ(pipe(given), 0);
  ASSERT_EQ(pipe2(err, O_CLOEXEC), 0);
  sigset_t blocked, old;
  sigemptyset(&blocked);
  sigaddset(&blocked, SIGTERM);
  sigaddset(&blocked, SIGUSR1);
  ASSERT_EQ(pthread_sigmask(SIG_BLOCK, &blocked, &old), 0);
  std::string error;
  const pid_t pid = start_child_process({sleep_program, "30"}, {{given[0], 3}}, err[1], &error);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  ASSERT_GT(pid, 0) << error;
  ASSERT_TRUE(wait_for_exec(pid, sleep_program));

  const std::string proc = "/proc/" + std::to_string(pid);
  std::set<std::string> fds;
  for (const auto& e : std::filesystem::directory_iterator(proc + "/fd"))
    fds.insert(e.path().filename().string());
  EXPECT_EQ(fds, (std::set<std::string>{"0", "1", "2", "3"}));
  EXPECT_EQ(link_of(proc + "/fd/0"), "/dev/null");
  EXPECT_EQ(link_of(proc + "/fd/1"), "/dev/null");
  EXPECT_EQ(link_of(proc + "/fd/2"), link_of("/proc/self/fd/" + std::to_string(err[1])));
  EXPECT_EQ(link_of(proc + "/fd/3"), link_of("/proc/self/fd/" + std::to_string(given[0])));
  std::ifstream status(proc + "/status");
  std::string line, sig_blk;
  while (std::getline(status, line))
    if (line.rfind("SigBlk:", 0) == 0) sig_blk = line;
  EXPECT_EQ(sig_blk, "SigBlk:\t0000000000000000");

  kill(pid, SIGKILL);
  int wait_status = 0;
  waitpid(pid, &wait_status, 0);
  for (int fd : {leaked, given[0], given[1], err[0], err[1]}) close(fd);
}

TEST(ChildProcess, StderrGoesWhereItIsSent) {
  int err[2];
  ASSERT_EQ(pipe2(err, O_CLOEXEC), 0);
  std::string error;
  const pid_t pid = start_child_process({"/bin/sh", "-c", "echo said >&2"}, {}, err[1], &error);
  ASSERT_GT(pid, 0) << error;
  close(err[1]);
  char buffer[64];
  const ssize_t n = read(err[0], buffer, sizeof buffer);
  close(err[0]);
  EXPECT_EQ(std::string(buffer, size_t(std::max<ssize_t>(n, 0))), "said\n");
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

// A helper of one rank of an MPI job must not start MPI as if it were a rank: the launcher's
// variables stay behind, everything else goes along.
TEST(ChildProcess, GetsNoMpiLauncherVariables) {
  int err[2];
  ASSERT_EQ(pipe2(err, O_CLOEXEC), 0);
  setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  setenv("PMIX_RANK", "1", 1);
  setenv("PMI_SIZE", "3", 1);
  setenv("FRACTALIS_TEST_KEPT", "kept", 1);
  std::string error;
  const pid_t shell = start_child_process({"/bin/sh", "-c", "env >&2"}, {}, err[1], &error);
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "FRACTALIS_TEST_KEPT"})
    unsetenv(name);
  ASSERT_GT(shell, 0) << error;
  close(err[1]);
  std::string environment;
  char buffer[4096];
  for (ssize_t n; (n = read(err[0], buffer, sizeof buffer)) > 0;) environment.append(buffer, n);
  close(err[0]);
  int status = 0;
  waitpid(shell, &status, 0);
  EXPECT_NE(environment.find("FRACTALIS_TEST_KEPT=kept"), std::string::npos) << environment;
  for (const char* name : {"OMPI_COMM_WORLD_SIZE=", "PMIX_RANK=", "PMI_SIZE="})
    EXPECT_EQ(environment.find(name), std::string::npos) << name;
}

TEST(ChildProcess, AMissingProgramIsAnExitStatus) {
  std::string error;
  const pid_t pid = start_child_process({"/no/such/program"}, {}, -1, &error);
  ASSERT_GT(pid, 0) << error;
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), kChildExecFailedStatus);
  EXPECT_EQ(start_child_process({}, {}, -1, &error), -1);
  EXPECT_EQ(error, "no program to start");
}

}  // namespace
}  // namespace fr
