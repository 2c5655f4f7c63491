// The render worker (worker/render_worker.hpp): frames that come back through it are the frames
// this process renders itself, and scene kernels that crash, hang, overrun, bomb the compiler or
// flood the output end the worker, never fractalis — for `list`, `render`, `bench`, `check` and
// `explore` (in a window under Xvfb), with the file and the reason named and nothing left behind.
// The hostile kernels are tests/fixtures/plugins/cl_*.c; explorer_window_test drives the overlay's
// slider into a crash.
#include "worker/render_worker.hpp"
#include "app/explorer.hpp"
#include "kernel_crash.hpp"
#include "platform/files.hpp"
#include "render/de_probe.hpp"
#include "test_support.hpp"
#include "worker/render_wire.hpp"

#ifdef _WIN32
#include <windows.h>
// (after windows.h)
#include <tlhelp32.h>
#else
#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <fstream>

namespace fr {
namespace {

namespace fs = std::filesystem;

const bool kWindows = fs::path::preferred_separator == '\\';

// What a write through a bad pointer in a kernel ends the render worker with (kernel_crash.hpp).
const std::string kSegv = test::kernel_crash_words();

fs::path kernel_fixture_dir(const std::string& name) {
  return fs::path(KERNEL_PLUGIN_DIR) / name;
}

// The worker under a name of this test's own, so that its processes can be counted among
// everything else that runs on the machine: a link to it (Linux), a copy (Windows, where a
// program's name is its file's).
fs::path own_worker() {
  static const fs::path own = [] {
    const fs::path dir = test::fresh_dir("render_worker_link");
    const fs::path target = fs::path(FRACTALIS_EXECUTABLE).parent_path() /
                            executable_file_name("fractalis-render-worker");
    const fs::path l = dir / executable_file_name("worker-" + std::to_string(current_process_id()));
    if (kWindows)
      fs::copy_file(target, l);
    else
      fs::create_symlink(target, l);
    return l;
  }();
  return own;
}

// Processes started from `program` (Linux: whose argv[0] it is; Windows: whose executable file
// has its name).
int processes_running(const fs::path& program) {
  int count = 0;
#ifdef _WIN32
  const HANDLE all = CreateToolhelp32Snapshot(TH32CS_SNAPPROCESS, 0);
  PROCESSENTRY32W entry{};
  entry.dwSize = sizeof entry;
  for (BOOL more = Process32FirstW(all, &entry); more; more = Process32NextW(all, &entry))
    if (_wcsicmp(entry.szExeFile, program.filename().c_str()) == 0) ++count;
  CloseHandle(all);
#else
  DIR* proc = opendir("/proc");
  while (dirent* e = readdir(proc)) {
    if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
    std::ifstream cmdline(std::string("/proc/") + e->d_name + "/cmdline");
    std::string argv0;
    std::getline(cmdline, argv0, '\0');
    if (argv0 == program.string()) ++count;
  }
  closedir(proc);
#endif
  return count;
}

struct CommandRun {
  int code = -1;
  std::string output;  // stdout and stderr
};

using Args = std::vector<std::string>;

Args operator+(Args a, const Args& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Runs the fractalis executable (a process of its own: if isolation failed, it, not the test,
// would die) with the test's own worker; `in_window` in an Xvfb of its own on Linux (the Windows
// tests run in one already: scripts/test-windows.sh).
CommandRun run_fractalis(const Args& args, bool in_window = false) {
  test::Environment environment = {{"FRACTALIS_RENDER_WORKER", own_worker().string()}};
  test::ProgramRun run;
#ifdef XVFB_RUN
  if (in_window) {
    // (SDL and the X libraries keep memory to the end, which LeakSanitizer would call leaks, as
    // in explorer_window_test.)
    environment.push_back({"ASAN_OPTIONS", "detect_leaks=0"});
    run = test::run_program(XVFB_RUN, Args{"-a", FRACTALIS_EXECUTABLE} + args, environment);
    return {run.exit_code, run.output + (run.exit_code < 0 ? "\n[" + run.how + "]" : "")};
  }
#else
  (void)in_window;
#endif
  run = test::run_program(FRACTALIS_EXECUTABLE, args, environment);
  return {run.exit_code, run.output + (run.exit_code < 0 ? "\n[" + run.how + "]" : "")};
}

// Limits short enough for a test: a hang ends in seconds, a compiler bomb in 6 s or 1 GiB. Each
// hostile scene meets them once per command (four commands), so they set the test's length; the
// scenes that do render build in well under a second and vet in about one. The vet's limit is
// well above the build's, so that the preprocessor bomb's build limit speaks first: the vet child
// also starts processes and loads the plugin, and under the sanitizers on a loaded 2-core
// machine (the Windows cross-build beside it) 2 s of margin was once not enough.
const Args kLimits = {
    "--set", "render.watchdog_s=5",       "--set", "plugins.vet_timeout_s=14",
    "--set", "plugins.build_timeout_s=6", "--set", "plugins.worker_memory_mib=1024"};

// Whether `text` says one of the alternatives ("a|b"), each a set of parts it must all contain
// ("a&b").
bool says_any(const std::string& text, const std::string& alternatives) {
  size_t at = 0;
  for (;;) {
    const size_t bar = alternatives.find('|', at);
    const std::string alternative = alternatives.substr(at, bar - at);
    bool all = true;
    for (size_t part = 0;;) {
      const size_t amp = alternative.find('&', part);
      if (text.find(alternative.substr(part, amp - part)) == std::string::npos) all = false;
      if (amp == std::string::npos) break;
      part = amp + 1;
    }
    if (all) return true;
    if (bar == std::string::npos) return false;
    at = bar + 1;
  }
}

struct Hostile {
  const char* name;      // fixture folder, and scene id after "kernel_"
  Args extra;            // extra options of render and bench
  std::string reason;    // what the error must say (says_any)
  bool renders = false;  // the scene renders (its attack is a nuisance, not a failure)
};

const Hostile kHostile[] = {
    {"write_everywhere", {}, kSegv},
    {"write_some_points", {}, kSegv},
    {"write_above_param", {"--param", "danger=1"}, kSegv},
    {"private_overrun", {}, kSegv + "|crashed (SIGBUS"},
    {"huge_private", {}, kSegv + "|crashed (|memory|compil"},
    {"preprocessor_bomb", {}, "SIGXFSZ|plugins.build_timeout_s|plugins.worker_memory_mib"},
    {"huge_source", {}, "de_source is longer than 1048576 bytes"},
    {"loop_some_pixels", {}, "did not finish"},
    // (Under Wine, PoCL's printf writes to the Linux descriptor 1 the process started with, not
    // to the Windows handle the worker was given: nothing reaches fractalis to cap.)
    {"printf_flood", {}, test::under_wine() ? "" : "printed more than 20 lines", true},
    {"macro_collision", {}, "fixture.cl:1: &v3_dot"},
    {"builtin_macro", {}, "rendered kernel_builtin_macro|median", true},
    {"function_collision", {}, "fixture.cl:4: &march"},
};

class HostileKernel : public testing::TestWithParam<Hostile> {};

TEST_P(HostileKernel, EveryCommandSurvivesAndNamesTheFileAndReason) {
  const Hostile& h = GetParam();
  const fs::path dir = kernel_fixture_dir(h.name);
  const std::string file = "kernel_" + std::string(h.name) + PLUGIN_SUFFIX;
  const Args plugins = {"--plugins", dir.string()};
  const Args scene = plugins + Args{"--scene", std::string("kernel_") + h.name} + kLimits + h.extra;
  const fs::path out = test::fresh_dir(std::string("render_worker_") + h.name);

  const CommandRun list = run_fractalis(Args{"list"} + plugins);
  // 1: a plugin failed to load (named, with its reason); never a crash of fractalis.
  EXPECT_TRUE(list.code == 0 || list.code == 1) << list.output;
  EXPECT_EQ(list.output.find('\033'), std::string::npos) << list.output;

  const CommandRun render = run_fractalis(
      Args{"render"} + scene + Args{"--size", "64x36", "--out", (out / "x.png").string()});
  const CommandRun bench = run_fractalis(Args{"bench"} + scene +
                                         Args{"--size", "64x36", "--frames", "2", "--runs", "1"});
  for (const CommandRun* r : {&render, &bench}) {
    SCOPED_TRACE(r->output);
    if (h.renders) {
      EXPECT_EQ(r->code, 0);
    } else {
      // An error (exit 1, or 3 for a time limit), not a crash of fractalis (128 + signal).
      EXPECT_TRUE(r->code == 1 || r->code == 3 || r->code == 2) << r->code;
      EXPECT_NE(r->output.find(file), std::string::npos) << "the file is named";
      if (std::string(h.name) == "loop_some_pixels") {
        EXPECT_EQ(r->code, 3) << "a time limit: the watchdog's status";
      }
    }
    EXPECT_TRUE(says_any(r->output, h.reason)) << "the reason: " << h.reason;
    EXPECT_EQ(r->output.find('\033'), std::string::npos) << "no escape reaches the terminal";
  }
  if (!h.renders) {
    EXPECT_FALSE(fs::exists(out / "x.png"));
  }
  size_t left = 0;
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().filename() != "x.png") ++left;
  EXPECT_EQ(left, 0u) << "no temporary file is left";

  // The explorer as a user starts it, in a window: the scene is skipped at load with its reason
  // (then status 2: no such scene), or explored, its error shown; never a crash of fractalis.
  const CommandRun explore =
      run_fractalis(Args{"explore"} + scene + Args{"--frames", "10", "--size", "64x36"}, true);
  {
    SCOPED_TRACE("explore: " + explore.output);
    EXPECT_TRUE(explore.code == 0 || (!h.renders && explore.code == 2)) << explore.code;
    if (!h.renders) {
      EXPECT_NE(explore.output.find(file), std::string::npos) << "the file is named";
      EXPECT_TRUE(says_any(explore.output, h.reason)) << "the reason: " << h.reason;
    }
  }

  const CommandRun check = run_fractalis(Args{"check", (dir / file).string()} + kLimits +
                                         Args{"--set", "plugins.allow_writable=true"});
  SCOPED_TRACE(check.output);
  EXPECT_TRUE(check.code == 0 || check.code == 1) << check.code;
  if (!h.renders && std::string(h.name) != "write_above_param" &&
      std::string(h.name) != "huge_source") {
    EXPECT_EQ(check.code, 1) << "the check fails";
  }
  EXPECT_EQ(processes_running(own_worker()), 0) << "no worker outlives fractalis";
}

INSTANTIATE_TEST_SUITE_P(Fixtures, HostileKernel, testing::ValuesIn(kHostile),
                         [](const auto& info) { return std::string(info.param.name); });

// The frames that come back through the worker's shared memory are the frames this process
// renders itself, pass for pass, at growing and shrinking sizes.
TEST(RenderWorker, FramesAreTheInProcessFrames) {
  const auto scene = test::mandelbulb();
  const SceneState state = make_default_state(scene->info);
  Renderer local(test::runtime());
  RenderWorker worker(test::runtime().device(), command_worker_limits(PluginPolicy{}, 600));
  for (const auto& [w, h, what] :
       {std::tuple{48, 27, Readback::Everything}, std::tuple{160, 90, Readback::DisplayAndSteps},
        std::tuple{33, 17, Readback::Display}}) {
    RenderSettings s;
    s.width_px = w;
    s.height_px = h;
    FrameImage mine, theirs;
    local.render_sample(scene->info, state, s, 0, what);
    local.finish(s, what, mine);
    worker.render_sample(scene->info, state, s, 0, what);
    worker.finish(s, what, theirs);
    EXPECT_EQ(theirs.width_px, w);
    EXPECT_EQ(theirs.height_px, h);
    EXPECT_EQ(theirs.lanes, mine.lanes);
    EXPECT_EQ(theirs.precision, mine.precision);
    EXPECT_EQ(theirs.rgba8, mine.rgba8);
    EXPECT_EQ(theirs.steps, mine.steps);
    EXPECT_EQ(theirs.ray_status, mine.ray_status);
    EXPECT_EQ(theirs.linear_rgba, mine.linear_rgba);
    EXPECT_EQ(theirs.depth, mine.depth);
    EXPECT_EQ(theirs.occlusion, mine.occlusion);
    EXPECT_EQ(theirs.shadow, mine.shadow);
    EXPECT_EQ(theirs.normal, mine.normal);
    EXPECT_EQ(theirs.albedo, mine.albedo);
    if (what == Readback::Everything) {
      EXPECT_GT(std::count(mine.ray_status.begin(), mine.ray_status.end(), 1), 100);
    }
  }
  const std::vector<std::array<float, 3>> points = {{0, 0, 3}, {0.1f, 0.2f, 0.3f}, {5, 5, 5}};
  EXPECT_EQ(worker.probe_de(scene->info, state.params, points),
            probe_de(test::runtime(), scene->info, state.params, points));
  EXPECT_EQ(worker.starts(), 1);
}

// The explorer's frame (render_frame: one round trip, read where it lies) is the frame this
// process renders with render_sample and finish, through the worker and in process, as the size
// grows and shrinks and the refinement's later samples read the display image only.
TEST(RenderWorker, ExplorerFramesAreTheInProcessFrames) {
  const auto scene = test::mandelbulb();
  const SceneState state = make_default_state(scene->info);
  Renderer local(test::runtime());
  for (const bool isolated : {true, false}) {
    PluginPolicy policy;
    policy.isolation = isolated ? PluginIsolation::Process : PluginIsolation::None;
    RenderWorker worker(test::runtime().device(), explorer_worker_limits(policy));
    for (const auto& [w, h, sample] :
         {std::tuple{160, 90, 0}, std::tuple{160, 90, 1}, std::tuple{320, 180, 0},
          std::tuple{33, 17, 0}, std::tuple{33, 17, 2}}) {
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " sample " +
                   std::to_string(sample) + (isolated ? " in the worker" : " in process"));
      RenderSettings s;
      s.width_px = w;
      s.height_px = h;
      const Readback read = sample == 0 ? Readback::DisplayAndSteps : Readback::Display;
      FrameImage mine;
      for (int i = 0; i <= sample; ++i)
        local.render_sample(scene->info, state, s, i, Readback::DisplayAndSteps);
      local.finish(s, read, mine);
      for (int i = 0; i < sample; ++i)
        worker.render_sample(scene->info, state, s, i, Readback::DisplayAndSteps);
      const FrameView theirs =
          worker.render_frame(scene->info, state, s, sample, Readback::DisplayAndSteps, read);
      const size_t n = static_cast<size_t>(w) * h;
      ASSERT_EQ(theirs.width_px, w);
      ASSERT_EQ(theirs.height_px, h);
      EXPECT_EQ(theirs.lanes, mine.lanes);
      EXPECT_EQ(theirs.precision, mine.precision);
      ASSERT_NE(theirs.rgba8, nullptr);
      EXPECT_EQ(std::vector<uint8_t>(theirs.rgba8, theirs.rgba8 + n * 4), mine.rgba8);
      if (sample == 0) {
        ASSERT_NE(theirs.steps, nullptr);
        ASSERT_NE(theirs.ray_status, nullptr);
        EXPECT_EQ(std::vector<float>(theirs.steps, theirs.steps + n), mine.steps);
        EXPECT_EQ(std::vector<uint8_t>(theirs.ray_status, theirs.ray_status + n), mine.ray_status);
        EXPECT_GT(count_rays(theirs).hit, n / 10);
      } else {
        EXPECT_EQ(theirs.steps, nullptr);
        EXPECT_EQ(theirs.ray_status, nullptr);
      }
    }
    EXPECT_EQ(worker.starts(), isolated ? 1 : 0);
  }
}

// More scenes than a worker holds at once (the explorer's reloads): the oldest make room, and one
// asked for again is sent again, not refused as unknown.
TEST(RenderWorker, MoreScenesThanItHoldsStillRender) {
  const auto scene = test::mandelbulb();
  const SceneState state = make_default_state(scene->info);
  RenderWorker worker(test::runtime().device(), command_worker_limits(PluginPolicy{}, 600));
  const std::vector<std::array<float, 3>> eye = {{0, 0, 3}};
  const float expected = worker.probe_de(scene->info, state.params, eye)[0];
  std::vector<SceneInfo> versions(kWorkerSceneCount + 3, scene->info);
  for (size_t i = 0; i < versions.size(); ++i) {
    versions[i].version = "reload " + std::to_string(i);  // another scene to the worker
    EXPECT_EQ(worker.probe_de(versions[i], state.params, eye)[0], expected) << i;
  }
  EXPECT_EQ(worker.probe_de(versions[0], state.params, eye)[0], expected) << "the first again";
  EXPECT_EQ(worker.starts(), 1);
}

// A kernel build error is an error of the call, not of the worker: it goes on.
TEST(RenderWorker, ABuildErrorKeepsTheWorker) {
  const auto scene = test::mandelbulb();
  RenderWorker worker(test::runtime().device(), command_worker_limits(PluginPolicy{}, 600));
  EXPECT_THROW(worker.build(scene->info, "kernel void k() { nonsense; }", "", "a broken program"),
               KernelBuildError);
  const SceneState state = make_default_state(scene->info);
  RenderSettings s;
  s.width_px = s.height_px = 8;
  EXPECT_NO_THROW(worker.render(scene->info, state, s));
  EXPECT_EQ(worker.starts(), 1);
}

std::shared_ptr<const LoadedScene> load_fixture(const std::string& name) {
  return test::load_or_fail(kernel_fixture_dir(name) / ("kernel_" + name + PLUGIN_SUFFIX));
}

// A crash names the file, the stage and the signal; the next call starts a fresh worker, which
// renders a good scene.
TEST(RenderWorker, ACrashEndsTheWorkerAndTheNextCallStartsAnother) {
  const auto bad = load_fixture("write_everywhere");
  const auto good = test::mandelbulb();
  RenderWorker worker(test::runtime().device(), command_worker_limits(PluginPolicy{}, 600));
  worker.name_scene_file(bad->info.id, bad->file);
  RenderSettings s;
  s.width_px = s.height_px = 16;
  try {
    worker.render(bad->info, make_default_state(bad->info), s);
    ADD_FAILURE() << "the crash went unseen";
  } catch (const RenderWorkerFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(bad->file.string()), std::string::npos) << what;
    EXPECT_TRUE(says_any(what, kSegv)) << what;
    EXPECT_NE(what.find("while rendering"), std::string::npos) << what;
    EXPECT_FALSE(e.timed_out());
  }
  const FrameImage image = worker.render(good->info, make_default_state(good->info), s);
  EXPECT_EQ(image.rgba8.size(), 16u * 16 * 4);
  EXPECT_EQ(worker.starts(), 2);
}

// A DE that never returns at some pixels ends at the frame limit, not later; a compiler bomb at
// the build limit (or the memory limit), in seconds.
TEST(RenderWorker, HangsAndBombsEndAtTheirLimits) {
  PluginPolicy policy;
  policy.build_timeout_s = 5;
  policy.worker_memory_mib = 1024;
  RenderWorker worker(test::runtime().device(), command_worker_limits(policy, 2));
  RenderSettings s;
  s.width_px = 64;
  s.height_px = 36;
  s.precision = Precision::Float;
  const auto loop = load_fixture("loop_some_pixels");
  auto start = std::chrono::steady_clock::now();
  try {
    worker.render(loop->info, make_default_state(loop->info), s);
    ADD_FAILURE() << "the hang went unseen";
  } catch (const RenderWorkerFailure& e) {
    EXPECT_TRUE(e.timed_out()) << e.what();
    EXPECT_NE(std::string(e.what()).find("did not finish within 2 s"), std::string::npos)
        << e.what();
  }
  auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2 + 5 + 10) << "the limit, a build and a fresh worker's start at most";

  const auto bomb = load_fixture("preprocessor_bomb");
  start = std::chrono::steady_clock::now();
  try {
    worker.render(bomb->info, make_default_state(bomb->info), s);
    ADD_FAILURE() << "the bomb went unseen";
  } catch (const std::exception& e) {
    EXPECT_TRUE(says_any(e.what(), "SIGXFSZ|plugins.build_timeout_s|plugins.worker_memory_mib"))
        << e.what();
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5 + 10);
}

// A DE's printf output is shown, escaped, attributed to its scene, and capped.
TEST(RenderWorker, PrintedOutputIsCappedAndAttributed) {
  if (test::under_wine())
    GTEST_SKIP() << "PoCL's printf bypasses Windows' handles under Wine (above)";
  std::ostringstream log;
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(log);
  auto previous = spdlog::default_logger();
  spdlog::set_default_logger(std::make_shared<spdlog::logger>("test", sink));
  const auto flood = load_fixture("printf_flood");
  {
    RenderWorker worker(test::runtime().device(), command_worker_limits(PluginPolicy{}, 600));
    worker.name_scene_file(flood->info.id, flood->file);
    RenderSettings s;
    s.width_px = 64;
    s.height_px = 36;
    worker.render(flood->info, make_default_state(flood->info), s);
    worker.render(flood->info, make_default_state(flood->info), s);
  }
  spdlog::set_default_logger(previous);
  const std::string text = log.str();
  size_t lines = 0;
  for (size_t at = 0; (at = text.find("printed", at)) != std::string::npos; ++at) ++lines;
  EXPECT_EQ(lines, 21u) << "20 lines, then one saying the rest is not shown:\n" << text;
  EXPECT_NE(text.find("scene 'kernel_printf_flood' (" + flood->file.string() + ") printed: flood"),
            std::string::npos)
      << text.substr(0, 2000);
  EXPECT_EQ(text.find('\033'), std::string::npos) << "escapes are escaped";
}

// The explorer shows the error of a parameter that crashes the worker, goes back to the last
// parameters that rendered, and renders them again in a fresh worker.
TEST(RenderWorker, TheExplorerGoesBackToTheLastGoodParameters) {
  RenderWorker worker(test::runtime().device(), explorer_worker_limits(PluginPolicy{}));
  std::vector<SceneEvent> events;
  SceneLibrary library({kernel_fixture_dir("write_above_param")}, PluginPolicy{}, RenderSettings{},
                       worker, &events);
  ASSERT_EQ(library.slots().size(), 1u);
  Explorer explorer(Settings{}, worker, library, "kernel_write_above_param");
  InputState input;
  explorer.update(input, 1.0 / 30, 0);
  ASSERT_NE(explorer.render(64, 36), nullptr);
  SceneSlot& slot = explorer.current();
  slot.state.params[0].v[0] = 1;  // what the overlay's slider does
  explorer.mark_changed();
  explorer.update(input, 1.0 / 30, 0);  // the probe at the eye runs the DE: the worker crashes
  const FrameView* frame = explorer.render(64, 36);
  EXPECT_TRUE(says_any(slot.error, kSegv)) << slot.error;
  EXPECT_NE(slot.error.find("kernel_write_above_param" PLUGIN_SUFFIX), std::string::npos)
      << slot.error;
  EXPECT_EQ(slot.state.params[0].v[0], 0) << "back to the last value that rendered";
  for (int i = 0; i < 3 && !frame; ++i) {
    explorer.update(input, 1.0 / 30, 0);
    frame = explorer.render(64, 36);
  }
  EXPECT_NE(frame, nullptr) << "a fresh worker renders again";
  EXPECT_GE(worker.starts(), 2);
}

// A scene that redefines an OpenCL built-in the march uses (fmax) keeps it to itself: its picture
// is the plain sphere's, pixel for pixel.
TEST(RenderWorker, ABuiltInMacroStaysInTheScenesCode) {
  const auto redefined = load_fixture("builtin_macro");
  const auto plain =
      test::load_or_fail(fs::path(FIXTURE_PLUGIN_DIR) / "fixture_valid_scene" PLUGIN_SUFFIX);
  RenderSettings s;
  s.width_px = 64;
  s.height_px = 36;
  const FrameImage a =
      test::worker().render(redefined->info, make_default_state(redefined->info), s, true);
  const FrameImage b = test::worker().render(plain->info, make_default_state(plain->info), s, true);
  EXPECT_EQ(a.rgba8, b.rgba8);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_GT(std::count(a.ray_status.begin(), a.ray_status.end(), 1), 200) << "the sphere is seen";
}

#ifndef _WIN32  // /proc, SIGKILL and waitpid
// Restarting the worker again and again leaves no descriptor, child or memory behind: 100 times in
// the suite, a thousand under the soak label (test::soak_rounds).
TEST(RenderWorker, RestartsLeakNothing) {
  const auto scene = test::mandelbulb();
  const SceneState state = make_default_state(scene->info);
  RenderWorker worker(test::runtime().device(), command_worker_limits(PluginPolicy{}, 600));
  const auto count_fds = [] {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator("/proc/self/fd")) ++n;
    return n;
  };
  const auto resident_kib = [] {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
      if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return 0L;
  };
  const std::vector<std::array<float, 3>> eye = {{0, 0, 3}};
  worker.probe_de(scene->info, state.params, eye);
  const size_t fds = count_fds();
  [[maybe_unused]] const long rss = resident_kib();
  const int kRestarts = test::soak_rounds(100);
  for (int i = 0; i < kRestarts; ++i) {
    kill(static_cast<pid_t>(worker.pid()), SIGKILL);
    EXPECT_THROW(worker.probe_de(scene->info, state.params, eye), RenderWorkerFailure);
    ASSERT_EQ(worker.probe_de(scene->info, state.params, eye).size(), 1u);
  }
  EXPECT_EQ(worker.starts(), kRestarts + 1);
  EXPECT_EQ(count_fds(), fds);
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), 0) << "no child left unreaped but the live worker";
#if !defined(FRACTALIS_TEST_SANITIZED)
  // (Under AddressSanitizer freed memory waits in its quarantine, so resident memory grows; there
  // LeakSanitizer checks for leaks when the test ends instead.)
  // 8 MiB over 100 restarts: a leak of 80 KiB a restart fails it, the frame buffers' page
  // churn does not.
  EXPECT_LT(resident_kib() - rss, 8 * 1024) << "KiB grown over " << kRestarts << " restarts";
#endif
}
#endif

}  // namespace
}  // namespace fr
