// Output files: what --out and --json do to what is already at the path (io/atomic_file.hpp),
// and that a signal during the write leaves no temporary file. Checked against the file system
// itself (lstat, permission bits, a reader on a FIFO), not against what the code reports.
#include "cli/cli.hpp"
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
// Runs fractalis with `args` in `dir` (stdout and stderr to /dev/null, SIGINT and SIGTERM at
// their defaults, as from a terminal: a shell running the tests in the background may have set
// SIGINT to be ignored, which fractalis rightly leaves alone) and sends `sig` the moment a file
// whose name starts with `watch_prefix` appears. Returns the wait status (also when it ended
// before the file appeared); *seen says whether the file appeared.
int signal_when_file_appears(const std::filesystem::path& dir, std::vector<std::string> args,
                             const std::string& watch_prefix, int sig, bool* seen) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(127);
    const int null_fd = open("/dev/null", O_WRONLY);
    dup2(null_fd, 1);
    dup2(null_fd, 2);
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    std::vector<char*> argv{const_cast<char*>(FRACTALIS_EXECUTABLE)};
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(FRACTALIS_EXECUTABLE, argv.data());
    _exit(127);
  }
  *seen = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!*seen && std::chrono::steady_clock::now() < deadline) {
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().filename().string().rfind(watch_prefix, 0) == 0) *seen = true;
    if (!*seen) {
      int early = 0;
      if (waitpid(pid, &early, WNOHANG) == pid) return early;  // finished before we saw it
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  if (*seen) kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

void kill_during_write(int sig, const std::vector<std::string>& args, const std::string& file) {
  const auto dir = test::fresh_dir(std::string("output_kill_") + strsignal(sig));
  std::ofstream(dir / "path.toml") << "[[keyframe]]\ntime_s = 0\neye = [0, 0, 3]\n"
                                      "target = [0, 0, 0]\n[[keyframe]]\ntime_s = 100\n"
                                      "eye = [0, 1, 3]\ntarget = [0, 0, 0]\n";
  bool seen = false;
  const int status = signal_when_file_appears(dir, args, "." + file + ".", sig, &seen);
  ASSERT_TRUE(seen) << "the temporary file was never seen: fractalis ended first, status " << status
                    << " (exit " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << ", signal "
                    << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << ")";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig)
      << "ended by the signal, not otherwise (status " << status << ")";
  std::string left;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename() != "path.toml") left += e.path().string() + " ";
  EXPECT_EQ(left, "") << "nothing is left behind";
}

// Rendered in bands, so that the temporary file exists for the whole render (a second or so),
// not only while one image is compressed: a loaded machine once let the whole image's shorter
// write pass unseen. A whole image is written through the same OutputFile.
const std::vector<std::string> kBandedRender = {
    "render", "--scene", "menger", "--size", "2400x2400", "--band-rows", "100", "--out", "big.png"};
TEST(OutputSafety, SigtermDuringTheWriteLeavesNoTemporaryFile) {
  kill_during_write(SIGTERM, kBandedRender, "big.png");
}
TEST(OutputSafety, CtrlCDuringTheWriteLeavesNoTemporaryFile) {
  kill_during_write(SIGINT, kBandedRender, "big.png");
}
// A video is written to its temporary file frame by frame: interrupted, nothing is left.
TEST(OutputSafety, CtrlCDuringAVideoLeavesNoTemporaryFile) {
  kill_during_write(
      SIGINT,
      {"animate", "--path", "path.toml", "--fps", "2", "--size", "64x48", "--out", "film.mkv"},
      "film.mkv");
}

// A PNG sequence interrupted after a few frames resumes with the frames that are missing only.
TEST(OutputSafety, InterruptedSequenceResumes) {
  const auto dir = test::fresh_dir("output_sequence");
  std::ofstream(dir / "path.toml") << "[[keyframe]]\ntime_s = 0\neye = [0, 0, 3]\n"
                                      "target = [0, 0, 0]\n[[keyframe]]\ntime_s = 4\n"
                                      "eye = [0, 1, 3]\ntarget = [0, 0, 0]\n";
  const std::vector<std::string> args = {"animate",
                                         "--path",
                                         (dir / "path.toml").string(),
                                         "--fps",
                                         "10",
                                         "--size",
                                         "160x120",
                                         "--samples",
                                         "8",
                                         "--out",
                                         (dir / "frames").string()};
  bool seen = false;
  std::filesystem::create_directory(dir / "frames");
  int status = signal_when_file_appears(dir / "frames", args, "frame_000003", SIGINT, &seen);
  (void)status;
  ASSERT_TRUE(seen);
  size_t before = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "frames"))
    before += e.path().extension() == ".png";
  ASSERT_LT(before, 41u);
  // The resumed run, in-process: it says how many were there and renders the rest.
  std::ostringstream out, err;
  const int code = run_cli(args, out, err);
  ASSERT_EQ(code, 0) << err.str();
  EXPECT_NE(out.str().find("resuming: " + std::to_string(before) + " of 41 frames"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("rendered " + std::to_string(41 - before) + " frames"),
            std::string::npos)
      << out.str();
  size_t pngs = 0, hidden = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "frames")) {
    pngs += e.path().extension() == ".png";
    hidden += e.path().filename().string().rfind(".frame_", 0) == 0;
  }
  EXPECT_EQ(pngs, 41u);
  EXPECT_EQ(hidden, 0u) << "no temporary frame left";
}

}  // namespace
}  // namespace fr
