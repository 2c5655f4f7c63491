// Hostile plugins against the host: one fixture per failure mode (fixtures/plugins/README.md has
// the table). For each, the host survives (this process goes on), the outcome names the file and
// the reason, and a good scene beside them still loads, updates and renders.
#include "io/printable.hpp"
#include "plugin/plugin_files.hpp"
#include "plugin/plugin_loader.hpp"
#include "plugin/scan_cache.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <elf.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>

namespace fr {
namespace {

std::filesystem::path hostile(const std::string& name) {
  return std::filesystem::path(HOSTILE_PLUGIN_DIR) / ("hostile_" + name + PLUGIN_SUFFIX);
}

// Short limits, so that the hanging fixtures cost little.
PluginPolicy quick_policy() {
  PluginPolicy p;
  p.load_timeout_s = 2;
  p.call_timeout_s = 0.5;
  return p;
}

// Processes this process has started and not yet reaped (zombies included).
size_t child_processes() {
  size_t n = 0;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream in(task.path() / "children");
    std::string pid;
    while (in >> pid) ++n;
  }
  return n;
}

size_t count_lines(const char* file, const std::string& part = "") {
  std::ifstream in(file);
  std::string line;
  size_t n = 0;
  while (std::getline(in, line))
    if (part.empty() || line.find(part) != std::string::npos) ++n;
  return n;
}

size_t open_files() {
  return static_cast<size_t>(
      std::distance(std::filesystem::directory_iterator("/proc/self/fd"), {}));
}

// Sets an environment variable for one scope, then puts back what was there.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    test::set_environment(name, value);
  }
  ~ScopedEnv() { test::set_environment(name_, old_); }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// The good neighbour: loads, creates, updates and renders an 8x8 image.
void expect_good_scene_works(const std::filesystem::path& file, const PluginPolicy& policy) {
  const LoadOutcome o = load_scene_plugin(file, policy);
  ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
  std::string error;
  auto instance = SceneInstance::create(o.scene, &error);
  ASSERT_TRUE(instance) << error;
  SceneState state = make_default_state(o.scene->info);
  ASSERT_TRUE(instance->update(state, 0.5, &error)) << error;
  Renderer renderer(test::runtime());
  RenderSettings settings;
  settings.width_px = settings.height_px = 8;
  const FrameImage image = renderer.render(o.scene->info, state, settings);
  EXPECT_EQ(image.rgba8.size(), 8u * 8u * 4u);
}

struct LoadExpectation {
  LoadResult result;
  std::string message_part;
};

// Every hostile fixture that must fail while loading, with its reason. Those that load (their
// attack comes later, in create or update) are listed as Loaded.
const std::map<std::string, LoadExpectation>& load_expectations() {
  static const std::map<std::string, LoadExpectation> e = {
      {"ctor_abort", {LoadResult::Crashed, "crashed (SIGABRT"}},
      {"ctor_segv", {LoadResult::Crashed, "crashed (SIG"}},
      {"ctor_loop", {LoadResult::Crashed, "did not answer within 2 s; it was stopped"}},
      {"ctor_exit", {LoadResult::Crashed, "exited with status 0"}},
      {"absurd_counts", {LoadResult::InvalidScene, "param_count 2000000000 is more than 256"}},
      {"too_many_lights",
       {LoadResult::InvalidScene, "light_count 9 is more than FR_MAX_SCENE_LIGHTS (8)"}},
      {"escape_name",
       {LoadResult::InvalidScene, "name is not clean text: control character 0x1b at byte 4"}},
      {"invalid_utf8",
       {LoadResult::InvalidScene, "description is not clean text: invalid UTF-8 at byte 3"}},
      {"reserved_nonzero", {LoadResult::InvalidScene, "fr_scene_desc.reserved is not zero"}},
      {"missing_dep",
       {LoadResult::NotLoadable, "libfixture_missing_dep_lib.so: cannot open shared object"}},
      {"create_crash", {LoadResult::Loaded, ""}},
      {"create_hang", {LoadResult::Loaded, ""}},
      {"create_throw", {LoadResult::Loaded, ""}},
      {"update_crash", {LoadResult::Loaded, ""}},
      {"update_throw", {LoadResult::Loaded, ""}},
      {"update_hang_later", {LoadResult::Loaded, ""}},
      {"update_exit", {LoadResult::Loaded, ""}},
      {"update_bad_camera", {LoadResult::Loaded, ""}},
      {"log_flood", {LoadResult::Loaded, ""}},
      {"de_loop", {LoadResult::Loaded, ""}},
  };
  return e;
}

// The whole hostile folder at once (loaded in parallel scene hosts), with a good scene among
// them: each outcome is the expected one, the good scene loads, and no process is left over.
TEST(PluginIsolation, HostileFolderLoadsWithEachFailureNamed) {
  const auto dir = test::fresh_dir("hostile_folder");
  for (const auto& [name, expected] : load_expectations())
    std::filesystem::copy_file(hostile(name), dir / (name + PLUGIN_SUFFIX));
  std::filesystem::copy_file(test::fixture_plugin("valid_scene"), dir / "valid" PLUGIN_SUFFIX);
  const size_t children_before = child_processes();
  const auto outcomes = load_scene_folder({dir}, quick_policy());
  ASSERT_EQ(outcomes.size(), load_expectations().size() + 1);
  for (const LoadOutcome& o : outcomes) {
    const std::string name = o.file.stem().string();
    EXPECT_EQ(o.file.parent_path(), dir) << "the outcome names the user's file";
    if (name == "valid") {
      EXPECT_EQ(o.result, LoadResult::Loaded) << o.message;
      continue;
    }
    const LoadExpectation& e = load_expectations().at(name);
    EXPECT_EQ(o.result, e.result) << name << ": " << load_result_name(o.result) << ": "
                                  << o.message;
    EXPECT_NE(o.message.find(e.message_part), std::string::npos) << name << " said: " << o.message;
    EXPECT_EQ(o.message.find("/proc/self/fd"), std::string::npos) << o.message;
    EXPECT_EQ(o.message.find("memfd"), std::string::npos) << o.message;
  }
  EXPECT_EQ(child_processes(), children_before) << "a scene host was left running or unreaped";
  expect_good_scene_works(dir / "valid" PLUGIN_SUFFIX, quick_policy());
}

// Attacks from create and update: each call fails with its reason, a failed update is not run
// again, and the process that ran it is gone.
struct CallExpectation {
  const char* fixture;
  bool create_fails;
  double update_time_s;  // the update that fails (earlier times must work)
  const char* message_part;
};

TEST(PluginIsolation, CallbacksThatCrashHangThrowOrLie) {
  const CallExpectation cases[] = {
      {"create_crash", true, 0, "its scene host crashed (SIG"},
      {"create_hang", true, 0, "did not answer within 0.5 s; it was stopped during create"},
      {"create_throw", true, 0,
       "create threw a C++ exception: fixture create threw (exceptions must not cross the C ABI)"},
      {"update_crash", false, 0, "its scene host crashed (SIG"},
      {"update_throw", false, 0, "update threw a C++ exception: fixture update threw"},
      {"update_exit", false, 0, "its scene host exited with status 0 during update"},
      {"update_bad_camera", false, 0, "update left an invalid camera: target equals eye"},
      {"update_hang_later", false, 1.5,
       "did not answer within 0.5 s; it was stopped during update"},
  };
  const size_t children_before = child_processes();
  for (const CallExpectation& c : cases) {
    SCOPED_TRACE(c.fixture);
    const LoadOutcome o = load_scene_plugin(hostile(c.fixture), quick_policy());
    ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
    std::string error;
    auto instance = SceneInstance::create(o.scene, &error);
    if (c.create_fails) {
      EXPECT_FALSE(instance);
      EXPECT_NE(error.find("scene '" + o.scene->info.id + "': "), std::string::npos) << error;
      EXPECT_NE(error.find(c.message_part), std::string::npos) << error;
      continue;
    }
    ASSERT_TRUE(instance) << error;
    SceneState state = make_default_state(o.scene->info);
    for (double t = 0; t < c.update_time_s; t += 0.5)
      ASSERT_TRUE(instance->update(state, t, &error)) << "t = " << t << ": " << error;
    const SceneState before = state;
    EXPECT_FALSE(instance->update(state, c.update_time_s, &error));
    EXPECT_NE(error.find(c.message_part), std::string::npos) << error;
    EXPECT_NE(error.find("its updates stop until the scene is reloaded"), std::string::npos);
    EXPECT_TRUE(instance->failed());
    EXPECT_EQ(state.camera.eye[2], before.camera.eye[2]) << "a failed update changed the state";
    // Not called again: the same reason comes back at once, even at a time that worked before.
    std::string again;
    EXPECT_FALSE(instance->update(state, 0, &again));
    EXPECT_EQ(again, error);
  }
  EXPECT_EQ(child_processes(), children_before);
  expect_good_scene_works(test::fixture_plugin("valid_scene"), quick_policy());
}

// A plugin that logs 10000 messages of 20 kB with escape sequences: the call still works (within
// the default time limit, under ASan too), and what reaches the log is bounded and escaped.
TEST(PluginIsolation, LogFloodIsBoundedAndEscaped) {
  const LoadOutcome o = load_scene_plugin(hostile("log_flood"), PluginPolicy{});
  ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
  std::string error;
  auto instance = SceneInstance::create(o.scene, &error);
  ASSERT_TRUE(instance) << error;
  SceneState state = make_default_state(o.scene->info);
  EXPECT_TRUE(instance->update(state, 0, &error)) << error;
  EXPECT_EQ(printable("\x1b[2J\xff ok"), "\\x1b[2J\\xff ok");
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\xc3\xa9");  // valid UTF-8 passes unchanged
}

// What a plugin folder may hold besides plugins: each is skipped with its reason, without
// opening it (a FIFO would block a reader forever), and the good plugin beside them loads.
TEST(PluginIsolation, FolderEntriesThatAreNotPlugins) {
  const auto dir = test::fresh_dir("odd_entries");
  std::filesystem::copy_file(test::fixture_plugin("valid_scene"), dir / "valid" PLUGIN_SUFFIX);
  std::filesystem::create_symlink("loop_b" PLUGIN_SUFFIX, dir / "loop_a" PLUGIN_SUFFIX);
  std::filesystem::create_symlink("loop_a" PLUGIN_SUFFIX, dir / "loop_b" PLUGIN_SUFFIX);
  std::filesystem::create_symlink("gone.so.1", dir / "dangling" PLUGIN_SUFFIX);
  ASSERT_EQ(mkfifo((dir / "fifo" PLUGIN_SUFFIX).c_str(), 0600), 0);
  std::filesystem::create_directory(dir / "folder" PLUGIN_SUFFIX);
  const int sock = socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string sock_path = (dir / "socket" PLUGIN_SUFFIX).string();
  ASSERT_LT(sock_path.size(), sizeof addr.sun_path);
  std::strcpy(addr.sun_path, sock_path.c_str());
  ASSERT_EQ(bind(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  // A symlink to a plugin is followed (and here gives a second copy of the same id).
  std::filesystem::create_symlink(dir / "valid" PLUGIN_SUFFIX, dir / "zz_link" PLUGIN_SUFFIX);
  // An ELF library built for another machine: the valid fixture with its e_machine changed.
  {
    std::ifstream in(test::fixture_plugin("valid_scene"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    Elf64_Ehdr eh;
    std::memcpy(&eh, bytes.data(), sizeof eh);
    eh.e_machine = eh.e_machine == EM_AARCH64 ? EM_X86_64 : EM_AARCH64;
    std::memcpy(bytes.data(), &eh, sizeof eh);
    std::ofstream(dir / "foreign" PLUGIN_SUFFIX, std::ios::binary) << bytes;
  }
  std::ofstream(dir / "notes.txt") << "not a plugin: ignored without a word";

  const std::map<std::string, std::pair<LoadResult, std::string>> expected = {
      {"loop_a", {LoadResult::Refused, "a symlink loop"}},
      {"loop_b", {LoadResult::Refused, "a symlink loop"}},
      {"dangling", {LoadResult::Refused, "a dangling symlink"}},
      {"fifo", {LoadResult::Refused, "a FIFO, not a shared library"}},
      {"folder", {LoadResult::Refused, "a directory, not a shared library"}},
      {"socket", {LoadResult::Refused, "a socket, not a shared library"}},
      {"foreign", {LoadResult::NotLoadable, "; this host is "}},
      {"zz_link", {LoadResult::DuplicateId, "duplicate scene id 'fixture_valid'"}},
      {"valid", {LoadResult::Loaded, ""}},
  };
  const auto outcomes = load_scene_folder({dir}, quick_policy());
  close(sock);
  EXPECT_EQ(outcomes.size(), expected.size());
  for (const LoadOutcome& o : outcomes) {
    const auto it = expected.find(o.file.stem().string());
    ASSERT_NE(it, expected.end()) << o.file;
    EXPECT_EQ(o.result, it->second.first) << o.file << ": " << o.message;
    EXPECT_NE(o.message.find(it->second.second), std::string::npos) << o.file << ": " << o.message;
  }
}

// Folders and files that another user could write to are refused, naming them, unless the
// settings allow it.
TEST(PluginIsolation, WritableByOthersIsRefusedUnlessAllowed) {
  const auto dir = test::fresh_dir("world_writable");
  std::filesystem::copy_file(test::fixture_plugin("valid_scene"), dir / "valid" PLUGIN_SUFFIX);
  ASSERT_EQ(chmod(dir.c_str(), 0777), 0);
  auto outcomes = load_scene_folder({dir}, quick_policy());
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_EQ(outcomes[0].result, LoadResult::Refused);
  EXPECT_EQ(outcomes[0].file, dir);
  EXPECT_NE(outcomes[0].message.find(dir.string() + " is writable by every user"),
            std::string::npos)
      << outcomes[0].message;
  EXPECT_NE(outcomes[0].message.find("plugins.allow_writable"), std::string::npos);
  PluginPolicy allow = quick_policy();
  allow.allow_writable = true;
  outcomes = load_scene_folder({dir}, allow);
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_EQ(outcomes[0].result, LoadResult::Loaded) << outcomes[0].message;

  ASSERT_EQ(chmod(dir.c_str(), 0755), 0);
  ASSERT_EQ(chmod((dir / "valid" PLUGIN_SUFFIX).c_str(), 0666), 0);
  const LoadOutcome file = load_scene_plugin(dir / "valid" PLUGIN_SUFFIX, quick_policy());
  EXPECT_EQ(file.result, LoadResult::Refused);
  EXPECT_NE(file.message.find("the file is writable by every user"), std::string::npos)
      << file.message;
}

// The old private copy went to $TMPDIR/fractalis-<uid>-<pid>/<n>-<name>, reusing a folder
// another user could plant. Here that folder is planted, with a symlink where the copy would go
// pointing at a file of the user's: loading, creating, updating and unloading (in a scene host
// and in-process) must leave that file alone and put nothing at all in the temp folder.
TEST(PluginIsolation, PlantedTempFolderIsNeverUsed) {
  const auto tmp = test::fresh_dir("planted_tmp");
  const auto victim = test::fresh_dir("planted_victim") / "precious.txt";
  std::ofstream(victim) << "mine";
  const auto planted =
      tmp / ("fractalis-" + std::to_string(getuid()) + "-" + std::to_string(getpid()));
  std::filesystem::create_directory(planted);
  for (int n = 0; n < 4; ++n)
    std::filesystem::create_symlink(
        victim, planted / (std::to_string(n) + "-fixture_valid_scene" PLUGIN_SUFFIX));
  {
    ScopedEnv tmpdir("TMPDIR", tmp.string());
    for (PluginIsolation mode : {PluginIsolation::Process, PluginIsolation::None}) {
      PluginPolicy policy = quick_policy();
      policy.isolation = mode;
      const LoadOutcome o = load_scene_plugin(test::fixture_plugin("valid_scene"), policy);
      ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
      std::string error;
      auto instance = SceneInstance::create(o.scene, &error);
      ASSERT_TRUE(instance) << error;
      SceneState state = make_default_state(o.scene->info);
      EXPECT_TRUE(instance->update(state, 0, &error)) << error;
    }
  }
  std::ifstream in(victim);
  std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(content, "mine");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(tmp), {}), 1) << "left something";
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(planted), {}), 4);
}

// By default no plugin code is mapped into the host: neither the file nor a private copy.
TEST(PluginIsolation, NoPluginCodeInTheHostByDefault) {
  const auto dir = test::fresh_dir("no_code_in_host");
  std::filesystem::copy_file(test::fixture_plugin("valid_scene"),
                             dir / "isolation_probe" PLUGIN_SUFFIX);
  // Mandelbulb: a scene with an update callback (a scene without callbacks needs no process).
  std::filesystem::copy_file(std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulb" PLUGIN_SUFFIX,
                             dir / "isolation_probe" PLUGIN_SUFFIX,
                             std::filesystem::copy_options::overwrite_existing);
  const LoadOutcome o = load_scene_plugin(dir / "isolation_probe" PLUGIN_SUFFIX);
  ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
  std::string error;
  auto instance = SceneInstance::create(o.scene, &error);
  ASSERT_TRUE(instance) << error;
  SceneState state = make_default_state(o.scene->info);
  EXPECT_TRUE(instance->update(state, 0, &error)) << error;
  EXPECT_EQ(count_lines("/proc/self/maps", "isolation_probe"), 0u);
  EXPECT_EQ(count_lines("/proc/self/maps", "fractalis-plugin"), 0u);
  EXPECT_GE(child_processes(), 1u) << "the update ran somewhere else";
  instance.reset();
  // In-process mode does map it: the check above can fail.
  PluginPolicy none;
  none.isolation = PluginIsolation::None;
  const LoadOutcome in_host = load_scene_plugin(dir / "isolation_probe" PLUGIN_SUFFIX, none);
  ASSERT_EQ(in_host.result, LoadResult::Loaded) << in_host.message;
  EXPECT_GT(count_lines("/proc/self/maps", "fractalis-plugin"), 0u);
}

// Loading, creating, updating and dropping a scene 200 times, isolated and in-process: no growth
// in open files, threads, mappings or child processes.
TEST(PluginIsolation, RepeatedLoadsLeakNothing) {
  for (PluginIsolation mode : {PluginIsolation::Process, PluginIsolation::None}) {
    PluginPolicy policy = quick_policy();
    policy.isolation = mode;
    auto cycle = [&] {
      const LoadOutcome o = load_scene_plugin(test::fixture_plugin("update_error"), policy);
      ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
      std::string error;
      auto instance = SceneInstance::create(o.scene, &error);
      ASSERT_TRUE(instance) << error;
      SceneState state = make_default_state(o.scene->info);
      EXPECT_FALSE(instance->update(state, 0, &error));
    };
    cycle();
    const size_t files = open_files(), maps = count_lines("/proc/self/maps");
    const auto thread_count = [] {
      return static_cast<size_t>(
          std::distance(std::filesystem::directory_iterator("/proc/self/task"), {}));
    };
    const size_t tasks = thread_count(), children = child_processes();
    for (int i = 0; i < 200; ++i) cycle();
    EXPECT_EQ(open_files(), files);
    EXPECT_EQ(thread_count(), tasks);
    EXPECT_EQ(child_processes(), children);
    EXPECT_LE(count_lines("/proc/self/maps"), maps + 2);  // the allocator may map an arena
  }
}

// A DE that never returns, in the commands that render one scene. Each first renders the scene
// at 8x8 in a child process, as the explorer does: `render`, `bench`, `animate` and `sweep` end
// after plugins.vet_timeout_s (not render.watchdog_s, here far longer), or its render's own
// plugins.vet_render_timeout_s when that is shorter, with exit status 3, an
// error naming the scene, its file and the limit, and nothing left behind. With isolation
// "none" (one process, for a debugger) there is no child: the watchdog ends them instead.
TEST(PluginIsolation, DeThatNeverReturnsEndsTheCommand) {
  struct Case {
    std::string command_out, extra, expected;
  };
  const std::string vetted = "scene 'fixture_de_loop' (PLUGINS/de_loop" PLUGIN_SUFFIX
                             "): a test render at 8x8 did not finish within "
                             "2 s (plugins.vet_timeout_s)";
  const std::string watchdog =
      "rendering scene 'fixture_de_loop' did not finish within 2 s (render.watchdog_s)";
  // The test render's own limit, shorter than the whole test's: said by it, soon.
  const std::string render_limit =
      "did not finish within 2 s (plugins.vet_render_timeout_s)";
  const std::vector<Case> cases = {
      {"render --out never.png", "--set render.watchdog_s=60", vetted},
      {"animate --out never.mkv --path path.toml", "--set render.watchdog_s=60", vetted},
      {"bench --frames 1 --runs 1", "--set render.watchdog_s=60", vetted},
      {"sweep --out sweep --knobs max_steps", "", vetted},
      {"render --out never.png",
       "--set plugins.vet_timeout_s=60 --set plugins.vet_render_timeout_s=2 "
       "--set render.watchdog_s=60",
       render_limit},
      {"render --out never.png", "--set plugins.isolation=none --set render.watchdog_s=2",
       watchdog},
      {"animate --out never.mkv --path path.toml",
       "--set plugins.isolation=none --set render.watchdog_s=2", watchdog},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.command_out + " " + c.extra);
    const auto dir = test::fresh_dir("de_loop_render");
    const auto plugins = dir / "plugins";
    std::filesystem::create_directories(plugins);
    std::filesystem::copy_file(hostile("de_loop"), plugins / "de_loop" PLUGIN_SUFFIX);
    std::ofstream(dir / "path.toml") << "[[keyframe]]\ntime_s = 0\neye = [0, 0, 3]\n"
                                        "target = [0, 0, 0]\n[[keyframe]]\ntime_s = 1\n"
                                        "eye = [0, 1, 3]\ntarget = [0, 0, 0]\n";
    const auto log = dir / "stderr.txt";
    // A cache of its own: nothing vetted before.
    const std::string command = "cd " + dir.string() + " && XDG_CACHE_HOME=" + dir.string() +
                                "/cache " + FRACTALIS_EXECUTABLE + " " + c.command_out +
                                " --plugins " + plugins.string() +
                                " --scene fixture_de_loop --size 16x16 --set "
                                "plugins.vet_timeout_s=2 " +
                                c.extra + " 2> " + log.string();
    const auto started = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    const double took_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    ASSERT_TRUE(WIFEXITED(status)) << command;
    EXPECT_EQ(WEXITSTATUS(status), 3) << command;
    EXPECT_LT(took_s, 40) << "within a limit, not after a minute: " << command;
    std::ifstream in(log);
    std::string said((std::istreambuf_iterator<char>(in)), {});
    for (size_t at; (at = said.find(plugins.string())) != std::string::npos;)
      said.replace(at, plugins.string().size(), "PLUGINS");
    EXPECT_NE(said.find(c.expected), std::string::npos) << said;
    std::vector<std::string> left;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (name != "stderr.txt" && name != "plugins" && name != "path.toml" && name != "cache")
        left.push_back(name);
    }
    EXPECT_TRUE(left.empty()) << command << " left " << left.front();
  }
}

// A good scene is vetted once per file content: the first `render` leaves one marker in
// $XDG_CACHE_HOME/fractalis/vetted/, the second adds none, a changed file adds one.
TEST(PluginIsolation, CommandsVetEachSceneFileOnce) {
  const auto dir = test::fresh_dir("vet_once");
  const auto plugins = dir / "plugins";
  std::filesystem::create_directories(plugins);
  std::filesystem::copy_file(std::filesystem::path(RELOAD_PLUGIN_DIR) / "reload_a" PLUGIN_SUFFIX,
                             plugins / "probe" PLUGIN_SUFFIX);
  const auto markers = dir / "cache" / "fractalis" / "vetted";
  auto render = [&] {
    const std::string command = "cd " + dir.string() + " && XDG_CACHE_HOME=" + dir.string() +
                                "/cache " + FRACTALIS_EXECUTABLE +
                                " render --out x.png --plugins " + plugins.string() +
                                " --scene reload_probe --size 16x16 -q";
    return std::system(command.c_str());
  };
  auto count = [&] {
    std::error_code ec;
    size_t n = 0;
    for (auto it = std::filesystem::directory_iterator(markers, ec);
         !ec && it != std::filesystem::directory_iterator(); ++it)
      ++n;
    return n;
  };
  ASSERT_EQ(render(), 0);
  EXPECT_EQ(count(), 1u);
  ASSERT_EQ(render(), 0);
  EXPECT_EQ(count(), 1u) << "the same bytes are not vetted again";
  std::filesystem::copy_file(std::filesystem::path(RELOAD_PLUGIN_DIR) / "reload_b" PLUGIN_SUFFIX,
                             plugins / "probe" PLUGIN_SUFFIX,
                             std::filesystem::copy_options::overwrite_existing);
  ASSERT_EQ(render(), 0);
  EXPECT_EQ(count(), 2u);
}

// A scan is kept by the file's identity: the second load of an unchanged file reads it back and
// starts no process, its callbacks still run (in a process started on first use), and a changed
// file is scanned again.
TEST(PluginIsolation, ScanIsCachedByFileIdentity) {
  const auto cache = test::fresh_dir("scan_cache_home");
  ScopedEnv cache_home("XDG_CACHE_HOME", cache.string());
  const auto dir = test::fresh_dir("scan_cache_plugins");
  std::filesystem::copy_file(std::filesystem::path(RELOAD_PLUGIN_DIR) / "reload_a" PLUGIN_SUFFIX,
                             dir / "cached" PLUGIN_SUFFIX);
  std::string error;
  const FileIdentity identity = [&] {
    const ReadableFile opened = open_plugin_file(dir / "cached" PLUGIN_SUFFIX, false, &error);
    EXPECT_TRUE(opened.valid()) << error;
    return opened.identity();
  }();
  EXPECT_FALSE(find_scan(identity));
  const LoadOutcome first = load_scene_plugin(dir / "cached" PLUGIN_SUFFIX, quick_policy());
  ASSERT_EQ(first.result, LoadResult::Loaded) << first.message;
  ASSERT_TRUE(find_scan(identity)) << "nothing kept in " << cache;
  const LoadOutcome second = load_scene_plugin(dir / "cached" PLUGIN_SUFFIX, quick_policy());
  ASSERT_EQ(second.result, LoadResult::Loaded) << second.message;
  EXPECT_EQ(second.scene->info.de_source, first.scene->info.de_source);
  auto instance = SceneInstance::create(second.scene, &error);
  ASSERT_TRUE(instance) << error;
  SceneState state = make_default_state(second.scene->info);
  EXPECT_TRUE(instance->update(state, 0, &error)) << error;
  // Rewritten in place with another build: another identity, scanned afresh.
  std::filesystem::copy_file(std::filesystem::path(RELOAD_PLUGIN_DIR) / "reload_b" PLUGIN_SUFFIX,
                             dir / "cached" PLUGIN_SUFFIX,
                             std::filesystem::copy_options::overwrite_existing);
  const LoadOutcome third = load_scene_plugin(dir / "cached" PLUGIN_SUFFIX, quick_policy());
  ASSERT_EQ(third.result, LoadResult::Loaded) << third.message;
  EXPECT_EQ(third.scene->info.version, "2.0.0");
  // The first scene's file changed under it: its process refuses to start on the new bytes.
  auto stale = SceneInstance::create(first.scene, &error);
  EXPECT_FALSE(stale);
  EXPECT_NE(error.find("changed since it was loaded"), std::string::npos) << error;
}

// A library the system could not load is not kept: what it lacked (here a shared library it
// needs) may be installed before the next scan, and then it loads.
TEST(PluginIsolation, AFailedLoadIsNotKept) {
  const auto cache = test::fresh_dir("scan_cache_missing_dep");
  ScopedEnv cache_home("XDG_CACHE_HOME", cache.string());
  const auto dir = test::fresh_dir("scan_cache_missing_dep_plugins");
  std::filesystem::copy_file(hostile("missing_dep"), dir / "needs_lib" PLUGIN_SUFFIX);
  const LoadOutcome before = load_scene_plugin(dir / "needs_lib" PLUGIN_SUFFIX, quick_policy());
  ASSERT_EQ(before.result, LoadResult::NotLoadable) << before.message;
  // "Installed": where the scene host's loader looks.
  ScopedEnv library_path("LD_LIBRARY_PATH", MISSING_DEP_LIB_DIR);
  const LoadOutcome after = load_scene_plugin(dir / "needs_lib" PLUGIN_SUFFIX, quick_policy());
  EXPECT_EQ(after.result, LoadResult::Loaded) << after.message;
}

}  // namespace
}  // namespace fr
