// The one launcher of helper processes (platform/child_process.hpp), its Linux side checked by
// looking at the child in /proc once it has exec'd: it has exactly stdin and stdout on
// /dev/null, the stderr it was given, the descriptors it was given at the numbers
// handle_in_child names, and none of ours (not even one opened without close-on-exec), and an
// empty signal mask although ours blocks signals. (What both systems share is in
// platform_test.cpp.)
#include "platform/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
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
  ChildSpec spec;
  spec.program = sleep_program;
  spec.arguments = {"30"};
  spec.handles = {given[0]};
  spec.stderr_to = err[1];
  auto child = ChildProcess::start(spec, &error);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  ASSERT_TRUE(child) << error;
  EXPECT_EQ(handle_in_child(0, given[0]), "3");
  const pid_t pid = static_cast<pid_t>(child->id());
  ASSERT_TRUE(wait_for_exec(pid, sleep_program));

  const std::string proc = "/proc/" + std::to_string(pid);
  // /proc shows the new program as soon as exec replaces the image, while its dynamic loader
  // may still hold a library open (at the lowest free number, 4): look again until the set is
  // what it should be, for at most 5 s. A descriptor the child inherited stays for good.
  const std::set<std::string> expected{"0", "1", "2", "3"};
  std::set<std::string> fds;
  for (int attempt = 0; attempt < 500; ++attempt) {
    fds.clear();
    for (const auto& e : std::filesystem::directory_iterator(proc + "/fd"))
      fds.insert(e.path().filename().string());
    if (fds == expected) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(fds, expected);
  EXPECT_EQ(link_of(proc + "/fd/0"), "/dev/null");
  EXPECT_EQ(link_of(proc + "/fd/1"), "/dev/null");
  EXPECT_EQ(link_of(proc + "/fd/2"), link_of("/proc/self/fd/" + std::to_string(err[1])));
  EXPECT_EQ(link_of(proc + "/fd/3"), link_of("/proc/self/fd/" + std::to_string(given[0])));
  std::ifstream status(proc + "/status");
  std::string line, sig_blk;
  while (std::getline(status, line))
    if (line.rfind("SigBlk:", 0) == 0) sig_blk = line;
  EXPECT_EQ(sig_blk, "SigBlk:\t0000000000000000");

  child->kill();
  EXPECT_TRUE(child->ended());
  for (int fd : {leaked, given[0], given[1], err[0], err[1]}) close(fd);
}

TEST(ChildProcess, StderrGoesWhereItIsSent) {
  int err[2];
  ASSERT_EQ(pipe2(err, O_CLOEXEC), 0);
  std::string error;
  ChildSpec spec;
  spec.program = "/bin/sh";
  spec.arguments = {"-c", "echo said >&2"};
  spec.stderr_to = err[1];
  auto child = ChildProcess::start(spec, &error);
  ASSERT_TRUE(child) << error;
  close(err[1]);
  char buffer[64];
  const ssize_t n = read(err[0], buffer, sizeof buffer);
  close(err[0]);
  EXPECT_EQ(std::string(buffer, size_t(std::max<ssize_t>(n, 0))), "said\n");
  ASSERT_TRUE(child->wait(-1));
  EXPECT_EQ(child->exit_status(), 0);
}

// A child killed by a signal is described by the signal's name.
TEST(ChildProcess, ASignalIsNamed) {
  ChildSpec spec;
  spec.program = "/bin/sh";
  spec.arguments = {"-c", "kill -SEGV $$"};
  std::string error;
  auto child = ChildProcess::start(spec, &error);
  ASSERT_TRUE(child) << error;
  ASSERT_TRUE(child->wait(10000));
  EXPECT_EQ(child->how_it_ended(), "crashed (SIGSEGV: Segmentation fault)");
  EXPECT_EQ(child->exit_status(), -1);
}

}  // namespace
}  // namespace fr
