// The platform layer (host/platform/): each stage against what the system itself says, on Linux
// in CTest and, cross-built with MinGW-w64, under Wine (scripts/test-windows.sh). One source for
// both: what a system is expected to answer is chosen at run time, never by #ifdef.
#include "platform/files.hpp"
#include "platform/folder_watch.hpp"
#include "platform/interrupt.hpp"
#include "platform/shared_memory.hpp"
#include "platform/system_facts.hpp"
#include "platform/user_folders.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <list>
#include <string>
#include <thread>

namespace fr {
namespace {

namespace fs = std::filesystem;

const bool kWindows = fs::path::preferred_separator == '\\';

void set_variable(const char* name, const std::string& value) {
  // setenv is POSIX, _putenv_s Windows'; putenv is both (the string must outlive the setting).
  static std::list<std::string> kept;  // never moves a string it holds
  kept.push_back(std::string(name) + "=" + value);
  putenv(kept.back().data());
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("fractalis-platform-test-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(UserFolders, FollowTheSystemsVariables) {
  const fs::path base = fs::temp_directory_path() / "fractalis-platform-folders";
  if (kWindows) {
    set_variable("LOCALAPPDATA", (base / "local").string());
    set_variable("APPDATA", (base / "roaming").string());
    EXPECT_EQ(user_folder(UserFolder::Cache), base / "local" / "fractalis" / "cache");
    EXPECT_EQ(user_folder(UserFolder::Data), base / "local" / "fractalis");
    EXPECT_EQ(user_folder(UserFolder::Config), base / "roaming" / "fractalis");
  } else {
    set_variable("XDG_CACHE_HOME", (base / "cache").string());
    set_variable("XDG_CONFIG_HOME", (base / "config").string());
    set_variable("XDG_DATA_HOME", (base / "data").string());
    EXPECT_EQ(user_folder(UserFolder::Cache), base / "cache" / "fractalis");
    EXPECT_EQ(user_folder(UserFolder::Config), base / "config" / "fractalis");
    EXPECT_EQ(user_folder(UserFolder::Data), base / "data" / "fractalis");
    // Unset (empty counts as unset): under HOME, as the XDG base directory specification says.
    set_variable("XDG_CACHE_HOME", "");
    set_variable("XDG_CONFIG_HOME", "");
    set_variable("XDG_DATA_HOME", "");
    set_variable("HOME", (base / "home").string());
    EXPECT_EQ(user_folder(UserFolder::Cache), base / "home" / ".cache" / "fractalis");
    EXPECT_EQ(user_folder(UserFolder::Config), base / "home" / ".config" / "fractalis");
    EXPECT_EQ(user_folder(UserFolder::Data), base / "home" / ".local" / "share" / "fractalis");
    set_variable("HOME", "");
    EXPECT_TRUE(user_folder(UserFolder::Cache).empty()) << "no HOME: no folder, not ./.cache";
  }
}

TEST(UserFolders, ExecutablePathIsThisTest) {
  const fs::path exe = executable_path();
  ASSERT_FALSE(exe.empty());
  EXPECT_TRUE(exe.is_absolute()) << exe;
  EXPECT_EQ(exe.stem(), "platform_test") << exe;
  EXPECT_TRUE(fs::is_regular_file(exe)) << exe;
}

TEST(SystemFacts, DescribeThisMachine) {
  const SystemFacts facts = system_facts();
  EXPECT_FALSE(facts.cpu_model.empty());
  EXPECT_GT(facts.memory_bytes, uint64_t{256} << 20) << "at least 256 MiB of memory";
  EXPECT_FALSE(facts.os.empty());
  const std::vector<MemoryBound> bounds = memory_bounds();
  ASSERT_FALSE(bounds.empty()) << "the memory available, at least";
  for (const MemoryBound& b : bounds) {
    EXPECT_FALSE(b.name.empty());
    EXPECT_GT(b.bytes_left, uint64_t{16} << 20) << b.name << ": this test itself runs";
  }
}

// Polls for up to 5 s (a watch reports within milliseconds; Wine's within its poll period).
bool changed_within_5_s(FolderWatch& watch) {
  for (int i = 0; i < 500; ++i) {
    if (watch.changed()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(FolderWatch, SaysWhenAFileAppearsChangesOrGoes) {
  const fs::path dir = fresh_dir("watch");
  FolderWatch watch(dir);
  ASSERT_TRUE(watch.active());
  EXPECT_FALSE(watch.changed()) << "nothing happened yet";
  std::ofstream(dir / "scene.so") << "first";
  EXPECT_TRUE(changed_within_5_s(watch)) << "a new file";
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  watch.changed();  // the writes' and closes' own events
  EXPECT_FALSE(watch.changed()) << "nothing since";
  std::ofstream(dir / "scene.so", std::ios::app) << " and more";
  EXPECT_TRUE(changed_within_5_s(watch)) << "a file written";
  fs::rename(dir / "scene.so", dir / "renamed.so");
  EXPECT_TRUE(changed_within_5_s(watch)) << "a file renamed";
  fs::remove(dir / "renamed.so");
  EXPECT_TRUE(changed_within_5_s(watch)) << "a file removed";
  fs::remove_all(dir);
}

TEST(FolderWatch, AFolderThatIsNotThereIsNotWatched) {
  FolderWatch watch(fs::temp_directory_path() / "fractalis-platform-test-no-such-folder");
  EXPECT_FALSE(watch.active());
  EXPECT_FALSE(watch.changed());
}

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Files, ExaminePathSaysWhatAPathNames) {
  const fs::path dir = fresh_dir("examine");
  EXPECT_EQ(examine_path(dir / "nothing").kind, PathKind::Missing);
  EXPECT_TRUE(examine_path(dir / "nothing").error.empty()) << "not there is not an error";
  EXPECT_EQ(examine_path(dir).kind, PathKind::Folder);
  std::ofstream(dir / "file") << "x";
  const PathInfo file = examine_path(dir / "file");
  EXPECT_EQ(file.kind, PathKind::Regular);
  EXPECT_FALSE(file.is_link);
  // The null device: written through, never replaced.
  EXPECT_EQ(examine_path(kWindows ? "NUL" : "/dev/null").kind, PathKind::CharacterDevice);
  std::error_code ec;
  fs::create_symlink(dir / "gone", dir / "dangling", ec);
  if (!ec) {  // (Windows lets only administrators and developer mode make symbolic links)
    const PathInfo dangling = examine_path(dir / "dangling");
    EXPECT_EQ(dangling.kind, PathKind::Missing);
    EXPECT_TRUE(dangling.is_link);
    EXPECT_FALSE(dangling.error.empty()) << "a link to nothing says why";
    fs::create_symlink(dir / "file", dir / "link", ec);
    EXPECT_EQ(examine_path(dir / "link").kind, PathKind::Regular);
    EXPECT_TRUE(examine_path(dir / "link").is_link);
  }
  EXPECT_FALSE(is_standard_output_path(dir / "file"));
  fs::remove_all(dir);
}

TEST(Files, WritableFileCreatesOnlyNewFilesAndReplacesInOneStep) {
  const fs::path dir = fresh_dir("writable");
  std::string error;
  bool exists = false;
  WritableFile a = WritableFile::create_new(dir / "temp", &exists, &error);
  ASSERT_TRUE(a.valid()) << error;
  EXPECT_FALSE(exists);
  WritableFile again = WritableFile::create_new(dir / "temp", &exists, &error);
  EXPECT_FALSE(again.valid()) << "never an existing file";
  EXPECT_TRUE(exists);
  EXPECT_FALSE(error.empty());
  ASSERT_TRUE(a.write_all("hello, world", &error)) << error;
  ASSERT_TRUE(a.seek(7, &error)) << error;
  ASSERT_TRUE(a.write_all("WORLD", &error)) << error;
  ASSERT_TRUE(a.set_mode(0640, &error)) << error;
  ASSERT_TRUE(a.flush_to_disk(&error)) << error;
  ASSERT_TRUE(a.close(&error)) << error;
  EXPECT_FALSE(a.valid());
  std::ofstream(dir / "target") << "old contents";
  ASSERT_TRUE(replace_file(dir / "temp", dir / "target", &error)) << error;
  EXPECT_EQ(read_all(dir / "target"), "hello, WORLD");
  EXPECT_FALSE(fs::exists(dir / "temp"));
  EXPECT_FALSE(replace_file(dir / "temp", dir / "target", &error)) << "nothing to move";
  EXPECT_EQ(read_all(dir / "target"), "hello, WORLD") << "the target stays";
  if (!kWindows) {
    EXPECT_EQ(examine_path(dir / "target").mode, 0640u);
  }
  WritableFile missing = WritableFile::create_new(dir / "no" / "folder", &exists, &error);
  EXPECT_FALSE(missing.valid());
  EXPECT_FALSE(exists);
  remove_file_now((dir / "target").string().c_str());
  EXPECT_FALSE(fs::exists(dir / "target"));
  fs::remove_all(dir);
}

// Another mapping of the same memory (the render worker's, here in this process) sees what the
// creator wrote, as the memory grows; and asking it for more than there is fails, not faults.
TEST(SharedMemory, BothSidesSeeTheSameBytesAsItGrows) {
  SharedMemory creator;
  creator.grow(1 << 20);
  ASSERT_GE(creator.mapped_bytes(), size_t{1} << 20);
  for (size_t i = 0; i < (size_t{1} << 20); i += 4096)
    creator.data()[i] = static_cast<uint8_t>(i >> 12);
  const intptr_t copy = creator.duplicate_handle();
  ASSERT_NE(copy, -1);
  SharedMemory helper(copy);
  std::string error;
  ASSERT_TRUE(helper.map_at_least(1 << 20, &error)) << error;
  for (size_t i = 0; i < (size_t{1} << 20); i += 4096)
    ASSERT_EQ(helper.data()[i], static_cast<uint8_t>(i >> 12)) << "byte " << i;
  helper.data()[5] = 42;
  EXPECT_EQ(creator.data()[5], 42) << "and the other way";
  EXPECT_FALSE(helper.map_at_least(size_t{64} << 20, &error)) << "more than there is";
  EXPECT_FALSE(error.empty());
  creator.grow(size_t{64} << 20);
  creator.data()[(size_t{64} << 20) - 1] = 7;
  ASSERT_TRUE(helper.map_at_least(size_t{64} << 20, &error)) << error;
  EXPECT_EQ(helper.data()[(size_t{64} << 20) - 1], 7);
  EXPECT_EQ(helper.data()[4096], 1) << "what was there before growing stays";
}

// Ctrl-C while a catcher lives sets the flag, and the process goes on.
TEST(Interrupt, CaughtWhileACatcherLives) {
  if (kWindows) GTEST_SKIP() << "Ctrl-C reaches a console program through its console (not here)";
  InterruptCatcher catcher;
  EXPECT_FALSE(InterruptCatcher::interrupted());
  std::raise(SIGINT);
  EXPECT_TRUE(InterruptCatcher::interrupted());
}

}  // namespace
}  // namespace fr
