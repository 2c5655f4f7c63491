// `mpirun -np N fractalis ...` on this one machine: the ranks share a poster's bands and an
// animation's frames, and the files are the ones a single process writes, byte for byte (PNG,
// EXR, a PNG folder) or frame for frame (a video, decoded). A rank that is killed or stopped ends
// the job with a message naming it and what it had, leaving nothing half-written; a PNG folder
// keeps its finished frames and resumes.
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::string kFractalis = FRACTALIS_EXECUTABLE;

fs::path test_dir(const std::string& name) {
  const fs::path dir = fs::path(TEST_OUTPUT_DIR) / "mpi" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct JobRun {
  int code = -1;
  std::string output;  // stdout and stderr
};

// `command` through the shell, its output (both streams) and exit status.
JobRun run(const std::string& command) {
  JobRun r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

std::string mpirun(int ranks) {
  return std::string(MPIEXEC) + " --oversubscribe --bind-to none -np " + std::to_string(ranks) +
         " ";
}

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every file of a folder (hidden ones too) and its bytes.
std::vector<std::pair<std::string, std::string>> folder_bytes(const fs::path& dir) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& e : fs::directory_iterator(dir))
    files.emplace_back(e.path().filename().string(), file_bytes(e.path()));
  std::sort(files.begin(), files.end());
  return files;
}

size_t count_of(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(Mpi, PostersAreTheSameFileFromOneTwoOrThreeRanks) {
  const fs::path dir = test_dir("poster");
  for (const std::string ext : {".png", ".exr"}) {
    const std::string args = " render --scene menger --size 203x131 --band-rows 9 --out ";
    const JobRun one = run(kFractalis + args + (dir / ("one" + ext)).string());
    ASSERT_EQ(one.code, 0) << one.output;
    for (const int ranks : {1, 2, 3}) {
      const fs::path file = dir / (std::to_string(ranks) + ext);
      const JobRun r = run(mpirun(ranks) + kFractalis + args + file.string());
      ASSERT_EQ(r.code, 0) << r.output;
      EXPECT_NE(r.output.find("in 15 bands"), std::string::npos) << r.output;
      EXPECT_EQ(file_bytes(file), file_bytes(dir / ("one" + ext))) << ranks << " ranks, " << ext;
    }
  }
  // One picture in one piece: rank 0 renders it, the same as one process does.
  const std::string args = " render --scene julia --size 96x64 --out ";
  ASSERT_EQ(run(kFractalis + args + (dir / "whole1.png").string()).code, 0);
  const JobRun r = run(mpirun(3) + kFractalis + args + (dir / "whole3.png").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(count_of(r.output, "rendered julia"), 1u) << r.output;
  EXPECT_EQ(file_bytes(dir / "whole3.png"), file_bytes(dir / "whole1.png"));
}

const char* kPath =
    "[[keyframe]]\ntime_s = 0\neye = [0, 0.5, 3]\ntarget = [0, 0, 0]\n\n"
    "[[keyframe]]\ntime_s = 1\neye = [2.5, 0.8, 1.5]\ntarget = [0, 0, 0]\n\n"
    "[[keyframe]]\ntime_s = 2\neye = [2.0, 1.5, -2]\ntarget = [0, 0, 0]\n";

fs::path write_path(const fs::path& dir) {
  std::ofstream(dir / "orbit.toml") << kPath;
  return dir / "orbit.toml";
}

// The decoded frames of a video, one checksum line each (ffmpeg's framemd5, without its header).
std::string decoded_frames(const fs::path& video) {
  const JobRun r = run("ffmpeg -v error -i " + video.string() + " -f framemd5 - | grep -v '^#'");
  return r.code == 0 ? r.output : "ffmpeg failed: " + r.output;
}

TEST(Mpi, AnimationsAreTheSameFromOneTwoOrThreeRanks) {
  const fs::path dir = test_dir("animate");
  const std::string args = " animate --scene sierpinski --path " + write_path(dir).string() +
                           " --fps 6 --size 96x54 --out ";
  ASSERT_EQ(run(kFractalis + args + (dir / "one").string()).code, 0);
  ASSERT_EQ(run(kFractalis + args + (dir / "one.mp4").string()).code, 0);
  const auto one_folder = folder_bytes(dir / "one");
  ASSERT_EQ(one_folder.size(), 14u);  // 13 frames and the record
  const std::string one_video = decoded_frames(dir / "one.mp4");
  ASSERT_EQ(count_of(one_video, "\n"), 13u) << one_video;
  for (const int ranks : {1, 2, 3}) {
    const fs::path folder = dir / std::to_string(ranks);
    const fs::path video = dir / (std::to_string(ranks) + ".mp4");
    JobRun r = run(mpirun(ranks) + kFractalis + args + folder.string());
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(folder_bytes(folder), one_folder) << ranks << " ranks";
    r = run(mpirun(ranks) + kFractalis + args + video.string());
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(decoded_frames(video), one_video) << ranks << " ranks";
  }
}

// A job started in the background, its ranks found by their environment.
struct BackgroundJob {
  fs::path log, status;

  BackgroundJob(const fs::path& dir, const std::string& command)
      : log(dir / "job.log"), status(dir / "job.status") {
    fs::remove(status);
    const std::string line = "(" + command + " > " + log.string() + " 2>&1; echo $? > " +
                             status.string() + ".tmp; mv " + status.string() + ".tmp " +
                             status.string() + ") &";
    EXPECT_EQ(std::system(line.c_str()), 0);
  }

  // The pid of `rank` of a fractalis job whose command line mentions `marker`, or -1.
  static pid_t rank_pid(int rank, const std::string& marker) {
    for (const auto& e : fs::directory_iterator("/proc")) {
      const std::string name = e.path().filename().string();
      if (name.find_first_not_of("0123456789") != std::string::npos) continue;
      std::string cmdline = file_bytes(e.path() / "cmdline");
      std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
      if (cmdline.find("fractalis") == std::string::npos ||
          cmdline.find(marker) == std::string::npos || cmdline.find("mpirun") != std::string::npos)
        continue;
      std::string environ = file_bytes(e.path() / "environ");
      std::replace(environ.begin(), environ.end(), '\0', '\n');
      if (("\n" + environ).find("\nOMPI_COMM_WORLD_RANK=" + std::to_string(rank) + "\n") !=
          std::string::npos)
        return static_cast<pid_t>(std::stol(name));
    }
    return -1;
  }

  // Waits up to `limit_s` for the job to end; its exit status, or -1 if it did not.
  int wait(double limit_s) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
    while (std::chrono::steady_clock::now() < until) {
      if (fs::exists(status)) return std::stoi(file_bytes(status));
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return -1;
  }
};

size_t frames_in(const fs::path& folder) {
  size_t n = 0;
  if (fs::exists(folder))
    for (const auto& e : fs::directory_iterator(folder))
      if (e.path().extension() == ".png" && e.path().filename().string()[0] != '.') ++n;
  return n;
}

// Nothing but frames and the record: no temporary file of a frame being written.
std::vector<std::string> strays_in(const fs::path& folder) {
  std::vector<std::string> strays;
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    if (name != ".fractalis-animation" && name.rfind("frame_", 0) != 0) strays.push_back(name);
  }
  return strays;
}

// Kills `rank` once `ready()` holds (within 120 s); false if it never did.
template <typename Ready>
bool kill_rank_when(int rank, const std::string& marker, int sig, Ready ready) {
  for (int i = 0; i < 1200; ++i) {
    if (ready()) {
      const pid_t pid = BackgroundJob::rank_pid(rank, marker);
      if (pid > 0 && kill(pid, sig) == 0) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

// The job ends within 60 s with a failure, rank 0 saying what the ranks had (`in_hand`), and
// `dir` holds nothing but `inputs` and the job's own log: no output, no temporary file.
void expect_failed_leaving_only(BackgroundJob& job, const fs::path& dir, const std::string& in_hand,
                                const std::set<std::string>& inputs) {
  const int code = job.wait(60);
  const std::string log = file_bytes(job.log);
  EXPECT_NE(code, 0) << log;
  EXPECT_NE(code, -1) << "the job did not end within 60 s\n" << log;
  EXPECT_NE(log.find(in_hand), std::string::npos) << log;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(inputs.count(name) || e.path() == job.log || e.path() == job.status) << name;
  }
}

const std::string kSlowFrames = " --scene mandelbulb --fps 12 --size 480x270 --samples 3 ";

TEST(Mpi, AKilledRankEndsTheJobAndTheFolderResumes) {
  const fs::path dir = test_dir("killed");
  const std::string path = write_path(dir).string();
  const fs::path folder = dir / "killed_frames";
  BackgroundJob job(dir, mpirun(3) + kFractalis + " animate" + kSlowFrames + "--path " + path +
                             " --out " + folder.string());
  ASSERT_TRUE(kill_rank_when(2, "killed_frames", SIGKILL, [&] { return frames_in(folder) >= 2; }));
  const int code = job.wait(60);
  const std::string log = file_bytes(job.log);
  EXPECT_NE(code, 0) << log;
  EXPECT_NE(code, -1) << "the job did not end within 60 s after rank 2 was killed\n" << log;
  // mpirun names the rank that died; rank 0 says what each rank had in hand.
  EXPECT_NE(log.find("rank 2"), std::string::npos) << log;
  EXPECT_NE(log.find("fractalis: the job ended while"), std::string::npos) << log;
  EXPECT_NE(log.find("had frame "), std::string::npos) << log;
  EXPECT_TRUE(strays_in(folder).empty()) << strays_in(folder)[0];
  const size_t kept = frames_in(folder);
  EXPECT_GE(kept, 2u);
  EXPECT_LT(kept, 25u);

  // The rest, with two ranks: only the missing frames, and the folder is one process's.
  const JobRun rest = run(mpirun(2) + kFractalis + " animate" + kSlowFrames + "--path " + path +
                          " --out " + folder.string());
  ASSERT_EQ(rest.code, 0) << rest.output;
  EXPECT_NE(rest.output.find("resuming: " + std::to_string(kept) + " of 25 frames are there"),
            std::string::npos)
      << rest.output;
  const JobRun one = run(kFractalis + " animate" + kSlowFrames + "--path " + path + " --out " +
                         (dir / "one").string());
  ASSERT_EQ(one.code, 0) << one.output;
  EXPECT_EQ(folder_bytes(folder), folder_bytes(dir / "one"));
}

TEST(Mpi, AKilledRankLeavesNoVideo) {
  const fs::path dir = test_dir("killed_video");
  const fs::path video = dir / "killed_video.mp4";
  BackgroundJob job(dir, mpirun(3) + kFractalis + " animate" + kSlowFrames + "--path " +
                             write_path(dir).string() + " --out " + video.string());
  // Some frames in (rank 0's progress lines say so): the video's temporary file is there.
  ASSERT_TRUE(kill_rank_when(1, "killed_video", SIGKILL, [&] {
    return file_bytes(job.log).find("frame 3/") != std::string::npos;
  }));
  expect_failed_leaving_only(job, dir, " had frame ", {"orbit.toml"});
}

TEST(Mpi, AKilledRankLeavesNoPoster) {
  const fs::path dir = test_dir("killed_poster");
  const fs::path poster = dir / "killed_poster.png";
  BackgroundJob job(dir, mpirun(3) + kFractalis +
                             " render --scene mandelbulb --size 1600x1200 --samples 4 "
                             "--band-rows 40 --out " +
                             poster.string());
  ASSERT_TRUE(kill_rank_when(2, "killed_poster", SIGKILL, [&] {
    return file_bytes(job.log).find("band 4/") != std::string::npos;
  }));
  expect_failed_leaving_only(job, dir, " had band ", {});
}

// A rank that stops answering (SIGSTOP: its own watchdog stops with it) ends the job within the
// watchdog's time and ten seconds, with a message naming the rank and its frame. (A watchdog of
// 5 s: at 2, a running rank's own frame under AddressSanitizer, beside CI's Windows build, once
// took longer, and its watchdog ended the job first.)
TEST(Mpi, AStoppedRankEndsTheJobInBoundedTime) {
  const fs::path dir = test_dir("stopped");
  const fs::path folder = dir / "stopped_frames";
  BackgroundJob job(dir, mpirun(3) + kFractalis + " animate" + kSlowFrames +
                             "--set render.watchdog_s=5 --path " + write_path(dir).string() +
                             " --out " + folder.string());
  ASSERT_TRUE(kill_rank_when(1, "stopped_frames", SIGSTOP, [&] { return frames_in(folder) >= 1; }));
  const auto stopped = std::chrono::steady_clock::now();
  const int code = job.wait(60);
  const double took_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - stopped).count();
  const std::string log = file_bytes(job.log);
  EXPECT_NE(code, 0) << log;
  EXPECT_NE(code, -1) << log;
  EXPECT_LT(took_s, 30) << log;
  EXPECT_NE(log.find("rank 1 has not finished frame "), std::string::npos) << log;
  EXPECT_TRUE(strays_in(folder).empty()) << strays_in(folder)[0];
}

// An error every rank would meet is said once, by rank 0, with the exit status one process
// gives; commands that share no work run on rank 0 alone.
TEST(Mpi, ErrorsAndOtherCommandsComeFromRankZeroAlone) {
  const fs::path dir = test_dir("errors");
  const JobRun bad = run(mpirun(3) + kFractalis + " animate --scene no_such_scene --path " +
                         write_path(dir).string() + " --out " + (dir / "x").string());
  EXPECT_EQ(bad.code, 2) << bad.output;
  EXPECT_EQ(count_of(bad.output, "unknown scene 'no_such_scene'"), 1u) << bad.output;
  const JobRun list = run(mpirun(3) + kFractalis + " list");
  EXPECT_EQ(list.code, 0) << list.output;
  EXPECT_EQ(count_of(list.output, "mandelbulb 1."), 1u) << list.output;  // its line, once
  const JobRun help = run(mpirun(2) + kFractalis + " render --help");
  EXPECT_EQ(help.code, 0);
  EXPECT_EQ(count_of(help.output, "usage: fractalis render"), 1u) << help.output;
}

// Without a launcher the same program is one process, as before: no MPI is started.
TEST(Mpi, WithoutALauncherItIsOneProcess) {
  const fs::path dir = test_dir("alone");
  const JobRun r = run(kFractalis + " render --scene menger --size 64x40 --band-rows 8 --out " +
                       (dir / "a.png").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output.find("ranks"), std::string::npos) << r.output;
}

}  // namespace
