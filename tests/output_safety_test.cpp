// Output files: what --out and --json do to what is already at the path (io/atomic_file.hpp),
// and that a signal during the write leaves no temporary file. Checked against the file system
// itself (lstat, permission bits, a reader on a FIFO), not against what the code reports.
#include "io/atomic_file.hpp"
#include "test_support.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <future>
#include <sstream>
#include <thread>

namespace fr {
namespace {

mode_t mode_of(const std::filesystem::path& file) {
  struct stat st {};
  EXPECT_EQ(stat(file.c_str(), &st), 0) << file;
  return st.st_mode & 07777;
}

size_t entries(const std::filesystem::path& dir) {
  return static_cast<size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

TEST(OutputSafety, RegularFilesKeepTheirModeAndNewOnesFollowTheUmask) {
  const auto dir = test::fresh_dir("output_modes");
  std::string error;
  const mode_t old_umask = umask(027);
  ASSERT_TRUE(write_file_atomic(dir / "new.txt", "one", &error)) << error;
  umask(old_umask);
  EXPECT_EQ(mode_of(dir / "new.txt"), 0640u);
  chmod((dir / "new.txt").c_str(), 0600);
  ASSERT_TRUE(write_file_atomic(dir / "new.txt", "two", &error)) << error;
  EXPECT_EQ(test::read_file(dir / "new.txt"), "two");
  EXPECT_EQ(mode_of(dir / "new.txt"), 0600u) << "the existing file's mode is kept";
  EXPECT_EQ(entries(dir), 1u) << "no temporary file left";
}

TEST(OutputSafety, SymlinkStaysALinkAndItsTargetIsWritten) {
  const auto dir = test::fresh_dir("output_symlink");
  std::filesystem::create_directory(dir / "real");
  std::ofstream(dir / "real" / "image.png") << "old";
  chmod((dir / "real" / "image.png").c_str(), 0604);
  std::filesystem::create_symlink("real/image.png", dir / "link.png");
  std::string error;
  ASSERT_TRUE(write_file_atomic(dir / "link.png", "new", &error)) << error;
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.png"));
  EXPECT_EQ(std::filesystem::read_symlink(dir / "link.png"), "real/image.png");
  EXPECT_EQ(test::read_file(dir / "real" / "image.png"), "new");
  EXPECT_EQ(mode_of(dir / "real" / "image.png"), 0604u);
  EXPECT_EQ(entries(dir / "real"), 1u);

  // A link to nothing is refused, and stays as it was.
  std::filesystem::create_symlink("missing.png", dir / "dangling.png");
  EXPECT_NE(output_problem(dir / "dangling.png").find("is a symlink to nothing"),
            std::string::npos);
  EXPECT_FALSE(write_file_atomic(dir / "dangling.png", "x", &error));
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "dangling.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "missing.png"));
}

TEST(OutputSafety, FifoAndCharacterDeviceAreWrittenThrough) {
  const auto dir = test::fresh_dir("output_fifo");
  const auto fifo = dir / "pipe.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  auto reader = std::async(std::launch::async, [&] { return test::read_file(fifo); });
  std::string error;
  ASSERT_TRUE(write_file_atomic(fifo, "through the pipe", &error)) << error;
  EXPECT_EQ(reader.get(), "through the pipe");
  struct stat st {};
  ASSERT_EQ(lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was not replaced";
  EXPECT_EQ(entries(dir), 1u);

  ASSERT_TRUE(write_file_atomic("/dev/null", "discarded", &error)) << error;
  ASSERT_EQ(stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/null is still a device";
}

TEST(OutputSafety, FoldersBlockDevicesAndSocketsAreRefused) {
  const auto dir = test::fresh_dir("output_refused");
  EXPECT_EQ(output_problem(dir), "is a folder, not a file");
  std::string error;
  EXPECT_FALSE(write_file_atomic(dir, "x", &error));
  for (const char* disk : {"/dev/loop0", "/dev/sda", "/dev/vda", "/dev/nvme0n1"}) {
    struct stat st {};
    if (stat(disk, &st) != 0 || !S_ISBLK(st.st_mode)) continue;
    EXPECT_NE(output_problem(disk).find("block device"), std::string::npos) << disk;
    EXPECT_FALSE(write_file_atomic(disk, "x", &error));
  }
  EXPECT_EQ(output_problem(dir / "new.png"), "") << "a new file is fine";
}

// `--out /dev/stdout`, redirected to a file or piped on: the output is the PNG alone, ending with
// its IEND chunk, and the report goes to stderr.
TEST(OutputSafety, StandardOutputCarriesOnlyThePng) {
  const auto dir = test::fresh_dir("output_stdout");
  const std::string render =
      std::string(FRACTALIS_EXECUTABLE) + " render --scene menger --size 16x16 --out /dev/stdout";
  for (const std::string& to : {std::string(" > "), std::string(" | cat > ")}) {
    const auto png = dir / "out.png", said = dir / "said.txt";
    const std::string command = render + " 2> " + said.string() + to + png.string();
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const std::string bytes = test::read_file(png);
    ASSERT_GT(bytes.size(), 20u) << command;
    EXPECT_EQ(bytes.substr(1, 3), "PNG") << command;
    EXPECT_EQ(bytes.substr(bytes.size() - 8), std::string("IEND\xae\x42\x60\x82", 8)) << command;
    EXPECT_NE(test::read_file(said).find("rendered menger 16x16"), std::string::npos) << command;
  }
}

// `fractalis render` killed by `sig` while its PNG's temporary file exists: the process ends by
// that signal and the folder is left empty.
void kill_during_write(int sig) {
  const auto dir = test::fresh_dir(std::string("output_kill_") + strsignal(sig));
  const std::string out = (dir / "big.png").string();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int null_fd = open("/dev/null", O_WRONLY);
    dup2(null_fd, 1);
    dup2(null_fd, 2);
    // As from a terminal: a shell running the tests in the background may have set SIGINT to
    // be ignored, which fractalis (rightly) leaves alone.
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    execl(FRACTALIS_EXECUTABLE, FRACTALIS_EXECUTABLE, "render", "--scene", "menger", "--size",
          "2400x2400", "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // Watch for the hidden temporary file and signal the moment it appears.
  bool seen = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!seen && std::chrono::steady_clock::now() < deadline) {
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().filename().string().rfind(".big.png.", 0) == 0) seen = true;
    if (!seen) {
      if (waitpid(pid, nullptr, WNOHANG) == pid) break;  // finished before we saw it
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  if (seen) kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(seen) << "the temporary file was never seen";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig)
      << "ended by the signal, not otherwise (status " << status << ")";
  std::string left;
  for (const auto& e : std::filesystem::directory_iterator(dir)) left += e.path().string() + " ";
  EXPECT_EQ(left, "") << "nothing is left behind";
}

TEST(OutputSafety, SigtermDuringTheWriteLeavesNoTemporaryFile) {
  kill_during_write(SIGTERM);
}
TEST(OutputSafety, CtrlCDuringTheWriteLeavesNoTemporaryFile) {
  kill_during_write(SIGINT);
}

}  // namespace
}  // namespace fr
