// The platform layer (host/platform/): each stage against what the system itself says, on Linux
// in CTest and, cross-built with MinGW-w64, under Wine (scripts/test-windows.sh). One source for
// both: what a system is expected to answer is chosen at run time, never by #ifdef.
#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "platform/files.hpp"
#include "platform/folder_watch.hpp"
#include "platform/interrupt.hpp"
#include "platform/shared_library.hpp"
#include "platform/shared_memory.hpp"
#include "platform/system_facts.hpp"
#include "platform/user_folders.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <list>
#include <memory>
#include <string>
#include <thread>
#include <vector>

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

// What a plugin holds shows in the heap count: 1 MiB in 4096 small blocks (from malloc's
// arenas) and 4 MiB in one (which glibc maps on its own), then gone again once freed.
TEST(SystemFacts, HeapBytesSeeWhatIsAllocated) {
  constexpr uint64_t kMiB = uint64_t{1} << 20;
  const uint64_t before = heap_bytes_in_use();
  std::vector<void*> small(4096);
  // The compiler may drop a malloc whose memory nothing reads; the empty asm reads it.
  const auto keep = [](void* p) { asm volatile("" : : "r"(p) : "memory"); };
  for (void*& p : small) keep(p = std::malloc(256));
  void* large = std::malloc(4 * kMiB);
  keep(large);
  const uint64_t holding = heap_bytes_in_use();
  EXPECT_GE(holding, before + 5 * kMiB) << before << " bytes before, " << holding << " holding";
  for (void* p : small) std::free(p);
  std::free(large);
  const uint64_t after = heap_bytes_in_use();
  EXPECT_LE(after + 4 * kMiB, holding) << holding << " bytes holding, " << after << " after";
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
  std::ofstream(dir / "scene" PLUGIN_SUFFIX) << "first";
  EXPECT_TRUE(changed_within_5_s(watch)) << "a new file";
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  watch.changed();  // the writes' and closes' own events
  EXPECT_FALSE(watch.changed()) << "nothing since";
  std::ofstream(dir / "scene" PLUGIN_SUFFIX, std::ios::app) << " and more";
  EXPECT_TRUE(changed_within_5_s(watch)) << "a file written";
  fs::rename(dir / "scene" PLUGIN_SUFFIX, dir / "renamed" PLUGIN_SUFFIX);
  EXPECT_TRUE(changed_within_5_s(watch)) << "a file renamed";
  fs::remove(dir / "renamed" PLUGIN_SUFFIX);
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

// A file opened for reading: what it is, all of its bytes (and no more than asked for), an
// identity that a replaced file does not share, and who else could change it.
TEST(Files, ReadableFileSaysWhatItOpenedAndReadsItWhole) {
  const fs::path dir = fresh_dir("readable");
  std::string contents(200000, '\0');
  for (size_t i = 0; i < contents.size(); ++i) contents[i] = static_cast<char>(i * 7 + i / 300);
  std::ofstream(dir / "plugin", std::ios::binary) << contents;
  std::string error;
  FileIdentity first;
  {
    const ReadableFile file = ReadableFile::open(dir / "plugin", &error);
    ASSERT_TRUE(file.valid()) << error;
    EXPECT_EQ(file.kind(), PathKind::Regular);
    EXPECT_EQ(file.identity().size_bytes, contents.size());
    std::string bytes;
    ASSERT_TRUE(file.read_all(contents.size(), &bytes, &error)) << error;
    EXPECT_TRUE(bytes == contents) << bytes.size() << " bytes read";
    ASSERT_TRUE(file.read_all(contents.size(), &bytes, &error)) << "again, from the start";
    EXPECT_TRUE(bytes == contents);
    EXPECT_FALSE(file.read_all(contents.size() - 1, &bytes, &error)) << "one byte over the limit";
    EXPECT_NE(error.find("more than"), std::string::npos) << error;
    EXPECT_EQ(file.others_who_can_write(), "") << "this test's own new file";
    first = file.identity();
  }  // (Windows replaces no file that is open)
  EXPECT_EQ(others_who_can_write(dir, true), "") << "this test's own new folder";

  {  // (the handles closed before the folder goes)
    // Replaced by another file of the same size: another identity.
    std::ofstream(dir / "next", std::ios::binary) << std::string(contents.size(), 'x');
    ASSERT_TRUE(replace_file(dir / "next", dir / "plugin", &error)) << error;
    const ReadableFile replaced = ReadableFile::open(dir / "plugin", &error);
    ASSERT_TRUE(replaced.valid()) << error;
    EXPECT_EQ(replaced.identity().size_bytes, first.size_bytes);
    EXPECT_FALSE(replaced.identity() == first);

    const ReadableFile folder = ReadableFile::open(dir, &error);
    ASSERT_TRUE(folder.valid()) << "a folder opens, to say what it is: " << error;
    EXPECT_EQ(folder.kind(), PathKind::Folder);
    EXPECT_EQ(describe(PathKind::Folder), "a directory");
    const ReadableFile missing = ReadableFile::open(dir / "nothing", &error);
    EXPECT_FALSE(missing.valid());
    EXPECT_EQ(error.rfind("cannot open: ", 0), 0u) << error;
    std::error_code ec;
    fs::create_symlink(dir / "gone", dir / "dangling", ec);
    if (!ec) {  // (Windows lets only administrators and developer mode make symbolic links)
      EXPECT_FALSE(ReadableFile::open(dir / "dangling", &error).valid());
      EXPECT_EQ(error, "a dangling symlink");
    }
  }
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

// The helper program these tests start (tests/platform_test_child.cpp), beside this test.
fs::path child_program() {
  const fs::path self = executable_path();
  return self.parent_path() / ("platform_test_child" + self.extension().string());
}

std::unique_ptr<ChildProcess> start_child(std::vector<std::string> arguments,
                                          std::vector<NativeHandle> handles = {}) {
  ChildSpec spec;
  spec.program = child_program();
  spec.arguments = std::move(arguments);
  spec.handles = std::move(handles);
  spec.stderr_to = own_stderr();
  std::string error;
  auto child = ChildProcess::start(spec, &error);
  EXPECT_TRUE(child) << error;
  return child;
}

// Everything `channel` gives until its other end closes (at most 10 s).
std::string read_to_end(Channel& channel) {
  std::string text;
  char buffer[256];
  for (int i = 0; i < 1000; ++i) {
    size_t got = 0;
    const ChannelStatus s = channel.read_some(buffer, sizeof buffer, 10000, &got);
    if (s != ChannelStatus::Ok) break;
    text.append(buffer, got);
  }
  return text;
}

// A child given one end of a channel, named as its last argument; `ours` is the other end.
struct ChildOnChannel {
  std::unique_ptr<ChildProcess> child;
  Channel ours;
};
ChildOnChannel start_on_channel(std::vector<std::string> arguments) {
  ChannelPair pair;
  std::string error;
  EXPECT_TRUE(make_channel_pair(&pair, &error)) << error;
  arguments.push_back(handle_in_child(0, pair.theirs.handle()));
  return {start_child(std::move(arguments), {pair.theirs.handle()}), std::move(pair.ours)};
  // pair.theirs closes here: the child has its own
}

// What a child wrote on its stdout (and its stderr too where `stderr_too`) through a pipe,
// without Windows' carriage returns, and its exit status (-2: it did not end).
struct ChildOutput {
  std::string text;
  int exit_status = -2;
};
ChildOutput output_of(std::vector<std::string> arguments, bool stderr_too = false) {
  ChildOutput out;
  ChannelPair pipe;
  std::string error;
  EXPECT_TRUE(make_pipe(&pipe, &error)) << error;
  ChildSpec spec;
  spec.program = child_program();
  spec.arguments = std::move(arguments);
  spec.stdout_to = pipe.theirs.handle();
  spec.stderr_to = stderr_too ? pipe.theirs.handle() : own_stderr();
  const auto child = ChildProcess::start(spec, &error);
  EXPECT_TRUE(child) << error;
  if (!child) return out;
  pipe.theirs.close();
  out.text = read_to_end(pipe.ours);
  out.text.erase(std::remove(out.text.begin(), out.text.end(), '\r'), out.text.end());
  if (child->wait(10000)) out.exit_status = child->exit_status();
  return out;
}

TEST(ChildProcess, TalksOverATwoWayChannel) {
  auto [child, ours] = start_on_channel({"echo"});
  ASSERT_TRUE(child);
  // Larger than a pipe's buffer, so that both ends must take turns.
  std::string sent(300000, '\0');
  for (size_t i = 0; i < sent.size(); ++i) sent[i] = static_cast<char>(i * 7 + i / 251);
  std::thread writer([&] { EXPECT_TRUE(ours.write_all(sent.data(), sent.size())); });
  std::string echoed;
  char buffer[8192];
  while (echoed.size() < sent.size()) {
    size_t got = 0;
    const ChannelStatus s = ours.read_some(buffer, sizeof buffer, 10000, &got);
    ASSERT_EQ(s, ChannelStatus::Ok) << "after " << echoed.size() << " bytes";
    echoed.append(buffer, got);
  }
  writer.join();
  EXPECT_TRUE(echoed == sent);
  ours.close();  // the child sees the end and exits 0
  ASSERT_TRUE(child->wait(10000));
  EXPECT_EQ(child->exit_status(), 0) << child->how_it_ended();
  EXPECT_EQ(child->how_it_ended(), "exited with status 0");
}

TEST(ChildProcess, StdoutThroughAPipeAndNoMpiLauncherVariables) {
  set_variable("OMPI_COMM_WORLD_SIZE", "3");
  set_variable("PMI_RANK", "1");
  set_variable("FRACTALIS_TEST_KEPT", "kept");
  const ChildOutput out =
      output_of({"env", "FRACTALIS_TEST_KEPT", "OMPI_COMM_WORLD_SIZE", "PMI_RANK"});
  EXPECT_EQ(out.text, "FRACTALIS_TEST_KEPT=kept\nOMPI_COMM_WORLD_SIZE unset\nPMI_RANK unset\n");
  EXPECT_EQ(out.exit_status, 0);
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_RANK", "FRACTALIS_TEST_KEPT"})
    set_variable(name, "");
}

TEST(ChildProcess, StdoutAndStderrCanShareAPipe) {
  const ChildOutput out = output_of({"print", "both"}, true);
  EXPECT_EQ(out.text, "both\n");
  EXPECT_EQ(out.exit_status, 0);
}

TEST(ChildProcess, ArgumentsArriveAsTheyWereGiven) {
  // Spaces, quotes and backslashes: Windows passes one command line the child splits again.
  for (const std::string text : {"two words", "a \"quoted\" word", "trailing\\",
                                 "back\\\\slash\\\"", "", "tab\there", "é ü 漢字"}) {
    const ChildOutput out = output_of({"print", text});
    EXPECT_EQ(out.exit_status, 0) << text;
    if (kWindows && text == "é ü 漢字") continue;  // the child's narrow argv is the code page's
    EXPECT_EQ(out.text, text + "\n");
  }
}

TEST(ChildProcess, SaysHowItEnded) {
  auto exits = start_child({"exit", "3"});
  ASSERT_TRUE(exits && exits->wait(10000));
  EXPECT_EQ(exits->how_it_ended(), "exited with status 3");
  EXPECT_EQ(exits->exit_status(), 3);

  auto crashes = start_child({"crash"});
  ASSERT_TRUE(crashes && crashes->wait(10000));
  EXPECT_EQ(crashes->how_it_ended().rfind("crashed (", 0), 0u) << crashes->how_it_ended();
  EXPECT_EQ(crashes->exit_status(), -1);

  auto hangs = start_child({"hang"});
  ASSERT_TRUE(hangs);
  EXPECT_FALSE(hangs->wait(200));
  EXPECT_FALSE(hangs->ended());
  hangs->kill();
  EXPECT_TRUE(hangs->ended());
  EXPECT_EQ(hangs->how_it_ended(), "was killed");

  ChildSpec missing;
  missing.program = fs::temp_directory_path() / "fractalis-no-such-program";
  std::string error;
  auto none = ChildProcess::start(missing, &error);
  // Linux knows only after the fork (exec fails in the child); Windows before.
  if (none) {
    ASSERT_TRUE(none->wait(10000));
    EXPECT_EQ(none->how_it_ended(), "could not be started (exec failed)");
  } else {
    EXPECT_FALSE(error.empty());
  }
  EXPECT_FALSE(ChildProcess::start(ChildSpec{}, &error));
  EXPECT_EQ(error, "no program to start");
}

// No helper outlives the process that started it, however that ends: here a child is killed
// while its own child holds a channel, which closes only when that grandchild is gone too.
TEST(ChildProcess, AHelpersHelpersEndWithIt) {
  auto [child, ours] = start_on_channel({"spawn-hang"});
  ASSERT_TRUE(child);
  char ready = 0;
  size_t got = 0;
  ASSERT_EQ(ours.read_some(&ready, 1, 20000, &got), ChannelStatus::Ok);
  ASSERT_EQ(ready, 'r');
  child->kill();
  EXPECT_EQ(ours.read_some(&ready, 1, 10000, &got), ChannelStatus::Closed)
      << "the grandchild still holds its end";
}

TEST(ChildProcess, ResidentBytesSeeWhatItHolds) {
  auto [child, ours] = start_on_channel({"memory", "96"});
  ASSERT_TRUE(child);
  char ready = 0;
  size_t got = 0;
  ASSERT_EQ(ours.read_some(&ready, 1, 20000, &got), ChannelStatus::Ok);
  EXPECT_GE(child->resident_bytes(), uint64_t{96} << 20);
  EXPECT_LT(child->resident_bytes(), uint64_t{1} << 30);
  ours.close();
  ASSERT_TRUE(child->wait(10000));
  EXPECT_EQ(child->exit_status(), 0);
  EXPECT_EQ(child->resident_bytes(), 0u) << "nothing once it ended";
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(SharedLibrary, LoadsAPrivateCopyOfTheBytesItWasGiven) {
  const fs::path built =
      executable_path().parent_path() / library_file_name("platform_test_library");
  const std::string bytes = file_bytes(built);
  ASSERT_GT(bytes.size(), 1000u) << built;
  EXPECT_EQ(check_library_bytes(bytes), "");
  std::string error;
  auto first = SharedLibrary::load_private_copy(bytes, "first", &error);
  ASSERT_TRUE(first) << error;
  auto* value = static_cast<int*>(const_cast<void*>(first->symbol("platform_test_value")));
  ASSERT_NE(value, nullptr);
  EXPECT_EQ(*value, 42);
  using Add = int (*)(int, int);
  const auto add = reinterpret_cast<Add>(const_cast<void*>(first->symbol("platform_test_add")));
  ASSERT_NE(add, nullptr);
  EXPECT_EQ(add(2, 3), 5);
  EXPECT_EQ(first->symbol("platform_test_missing"), nullptr);
  // The same bytes again are a library of their own (a hot reload of an unchanged file must not
  // get the old one back), with their own data.
  *value = 7;
  auto second = SharedLibrary::load_private_copy(bytes, "second", &error);
  ASSERT_TRUE(second) << error;
  auto* second_value = static_cast<const int*>(second->symbol("platform_test_value"));
  ASSERT_NE(second_value, nullptr);
  EXPECT_EQ(*second_value, 42);
  EXPECT_EQ(*value, 7);
  first.reset();
  EXPECT_EQ(*second_value, 42) << "unloading one leaves the other";
  second.reset();
  if (kWindows) {  // the copies are files there: none is left once unloaded
    size_t left = 0;
    std::error_code ec;
    for (const auto& e :
         fs::directory_iterator(user_folder(UserFolder::Cache) / "plugin-copies", ec))
      left += e.path().extension() == ".dll";
    EXPECT_EQ(left, 0u);
  }
}

TEST(SharedLibrary, RefusesWhatIsNotAWholeLibraryForThisHost) {
  const fs::path built =
      executable_path().parent_path() / library_file_name("platform_test_library");
  const std::string bytes = file_bytes(built);
  ASSERT_GT(bytes.size(), 4000u);
  std::string error;
  EXPECT_FALSE(SharedLibrary::load_private_copy("hello, loader", "text", &error));
  EXPECT_EQ(error.rfind("not a", 0), 0u) << error;
  EXPECT_FALSE(SharedLibrary::load_private_copy("", "empty", &error));
  EXPECT_EQ(error.rfind("not a", 0), 0u) << error;
  EXPECT_FALSE(SharedLibrary::load_private_copy(bytes.substr(0, bytes.size() / 2), "half", &error));
  EXPECT_EQ(error.rfind("truncated", 0), 0u) << error;
  // This test program is a program, not a library: a PE header says so (a position-independent
  // ELF program is a shared object as far as its header goes, so only Windows can tell).
  if (kWindows) {
    EXPECT_NE(check_library_bytes(file_bytes(executable_path())), "");
  }
}

TEST(Channel, ReadsWaitAtMostTheirTimeAndSeeTheEnd) {
  ChannelPair pair;
  std::string error;
  ASSERT_TRUE(make_channel_pair(&pair, &error)) << error;
  char buffer[16];
  size_t got = 0;
  EXPECT_EQ(pair.ours.read_some(buffer, sizeof buffer, 0, &got), ChannelStatus::TimedOut);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(pair.ours.read_some(buffer, sizeof buffer, 100, &got), ChannelStatus::TimedOut);
  const double waited_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(waited_ms, 90);
  EXPECT_LT(waited_ms, 5000);
  Channel* both[] = {&pair.ours, &pair.theirs};
  EXPECT_EQ(wait_readable(both, 2, 50), -1);
  ASSERT_TRUE(pair.theirs.write_all("abc", 3));
  EXPECT_EQ(wait_readable(both, 2, 1000), 0);
  ASSERT_EQ(pair.ours.read_some(buffer, sizeof buffer, 0, &got), ChannelStatus::Ok);
  EXPECT_EQ(std::string(buffer, got), "abc");
  pair.theirs.close();
  EXPECT_EQ(wait_readable(both, 2, 1000), 0) << "the end is something to read";
  EXPECT_EQ(pair.ours.read_some(buffer, sizeof buffer, 1000, &got), ChannelStatus::Closed);
  EXPECT_FALSE(pair.ours.write_all("x", 1)) << "nobody at the other end";
  // A pipe whose reader is gone: false, and this process goes on (no SIGPIPE).
  ChannelPair pipe;
  ASSERT_TRUE(make_pipe(&pipe, &error)) << error;
  pipe.ours.close();
  EXPECT_FALSE(pipe.theirs.write_all("x", 1));
  EXPECT_EQ(handle_from_argument("x"), kNoHandle);
  EXPECT_EQ(handle_from_argument(""), kNoHandle);
}

}  // namespace
}  // namespace fr
