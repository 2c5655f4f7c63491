// The host's files that build on the platform layer alone and so already run on Windows: atomic
// output files (io/atomic_file.hpp), the plugin folder watcher (plugin/plugin_watcher.hpp) and
// the plugin folder's scan (plugin/plugin_files.hpp), checked the same way on Linux in CTest
// and, cross-built, under Wine (scripts/test-windows.sh). (tests/output_safety_test.cpp and
// tests/plugin_isolation_test.cpp check the Linux-only cases: FIFOs, symlinks, modes, signals.)
#include "io/atomic_file.hpp"
#include "plugin/plugin_files.hpp"
#include "plugin/plugin_watcher.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace fr {
namespace {

namespace fs = std::filesystem;

const bool kWindows = fs::path::preferred_separator == '\\';

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("fractalis-ported-test-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

size_t entries(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, AppearsWholeReplacesAndLeavesNothingBehind) {
  const fs::path dir = fresh_dir("atomic");
  std::string error;
  ASSERT_TRUE(write_file_atomic(dir / "out.txt", "first", &error)) << error;
  EXPECT_EQ(read_all(dir / "out.txt"), "first");
  ASSERT_TRUE(write_file_atomic(dir / "out.txt", "second, longer", &error)) << error;
  EXPECT_EQ(read_all(dir / "out.txt"), "second, longer");
  EXPECT_EQ(entries(dir), 1u) << "no temporary file left";
  {
    auto out = OutputFile::open(dir / "abandoned.txt", &error);
    ASSERT_NE(out, nullptr) << error;
    ASSERT_TRUE(out->write("half", &error)) << error;
    EXPECT_TRUE(out->seekable());
  }  // destroyed without commit: nothing appears, nothing stays
  EXPECT_FALSE(fs::exists(dir / "abandoned.txt"));
  EXPECT_EQ(entries(dir), 1u);
  EXPECT_FALSE(write_file_atomic(dir / "no" / "folder.txt", "x", &error));
  EXPECT_NE(error.find("folder.txt"), std::string::npos) << error;
  EXPECT_EQ(entries(dir), 1u);
  fs::remove_all(dir);
}

TEST(AtomicFile, AFolderIsRefusedAndTheNullDeviceWrittenThrough) {
  const fs::path dir = fresh_dir("refused");
  EXPECT_EQ(output_problem(dir), "is a folder, not a file");
  std::string error;
  EXPECT_FALSE(write_file_atomic(dir, "x", &error));
  EXPECT_NE(error.find("folder"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_directory(dir)) << "the folder is untouched";
  const fs::path null_device = kWindows ? "NUL" : "/dev/null";
  EXPECT_EQ(output_problem(null_device), "");
  auto out = OutputFile::open(null_device, &error);
  ASSERT_NE(out, nullptr) << error;
  EXPECT_FALSE(out->seekable()) << "written through, nothing replaced";
  EXPECT_TRUE(out->write("gone", &error)) << error;
  EXPECT_TRUE(out->commit(&error)) << error;
  fs::remove_all(dir);
}

// Polls with the watcher's clock `*now_s` advancing 0.05 s per look (and 20 ms of real time, for
// the system's notification to arrive) until something is reported, for at most 10 s of its
// clock: past 5 s the watcher scans anyway (its safety net).
std::vector<PluginChange> poll_until_reported(PluginWatcher& watcher, double* now_s) {
  for (int i = 0; i < 200; ++i) {
    *now_s += 0.05;
    std::vector<PluginChange> changes = watcher.poll(*now_s);
    if (!changes.empty()) return changes;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return {};
}

// A new plugin file (a library by this system's suffix) is reported once it has stayed the same
// for the debounce time, a removed one as removed; files there at the start are known, not new,
// and other files are no plugins at all.
TEST(PluginWatcher, ReportsFilesOnceTheyAreStable) {
  const fs::path dir = fresh_dir("watcher");
  const std::string suffix = kWindows ? ".dll" : ".so";
  std::ofstream(dir / ("old" + suffix)) << "there before";
  PluginWatcher watcher(dir, 0.3, 0.5);
  double now_s = 0;
  EXPECT_TRUE(watcher.poll(now_s).empty()) << "known at the start";
  std::ofstream(dir / "notes.txt") << "not a plugin";
  std::ofstream(dir / ("new" + suffix)) << "scene";
  const double written_s = now_s;
  auto changes = poll_until_reported(watcher, &now_s);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].kind, PluginChange::Kind::Added);
  EXPECT_EQ(changes[0].file.filename(), "new" + suffix);
  EXPECT_GE(now_s - written_s, 0.3) << "not before it was stable for the debounce time";
  fs::remove(dir / ("old" + suffix));
  changes = poll_until_reported(watcher, &now_s);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].kind, PluginChange::Kind::Removed);
  EXPECT_EQ(changes[0].file.filename(), "old" + suffix);
  fs::remove_all(dir);
}

// A plugin folder's scan: libraries by their system's suffix, anything else of that name skipped
// with its reason, other names ignored; this test's own folder (and its parents) not refused.
TEST(PluginFiles, ListsLibrariesAndSaysWhyTheRestAreSkipped) {
  const fs::path dir = fresh_dir("plugin-files");
  const std::string suffix = kWindows ? ".dll" : ".so";
  std::ofstream(dir / ("scene" + suffix)) << "bytes the loader will judge";
  fs::create_directory(dir / ("folder" + suffix));
  std::ofstream(dir / "notes.txt") << "not a plugin";
  // Windows ignores the case of names, so a `.DLL` is a library there; a `.SO` is none on Linux.
  std::ofstream(dir / (kWindows ? "upper.DLL" : "upper.SO")) << "bytes";
  const std::vector<PluginFile> files = list_plugin_files(dir, false);
  ASSERT_EQ(files.size(), kWindows ? 3u : 2u) << (files.empty() ? "" : files[0].skip_reason);
  EXPECT_EQ(files[0].path.filename(), "folder" + suffix);
  EXPECT_EQ(files[0].skip_reason, "a directory, not a shared library");
  EXPECT_EQ(files[1].path.filename(), "scene" + suffix);
  EXPECT_EQ(files[1].skip_reason, "");
  if (kWindows) {
    EXPECT_EQ(files[2].path.filename(), "upper.DLL");
  }
  std::string error;
  {
    const ReadableFile opened = open_plugin_file(dir / ("scene" + suffix), false, &error);
    EXPECT_TRUE(opened.valid()) << error;
    EXPECT_FALSE(open_plugin_file(dir / ("folder" + suffix), false, &error).valid());
    EXPECT_EQ(error, "a directory, not a shared library");
    EXPECT_FALSE(open_plugin_file(dir / ("gone" + suffix), false, &error).valid());
    EXPECT_EQ(error.rfind("cannot open: ", 0), 0u) << error;
  }
  EXPECT_EQ(list_plugin_files(dir / "missing", false).size(), 1u) << "one entry saying why";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fr
