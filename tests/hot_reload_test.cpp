// Hot reload, against a running scene library (the explorer's, headless): the test copies new,
// changed, broken and removed plugins into its folder and polls like the explorer's frame loop.
// Checks: a new scene appears within 2 s of the poll's own clock (after the debounce time); a
// changed one reloads keeping parameter values by key; a broken build leaves the old one running
// with the error kept; a removed one keeps running; and 50 reloads grow neither open files nor
// threads, and leave one copy of the library mapped.
#include "app/explorer.hpp"
#include "app/scene_library.hpp"
#include "io/log.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <chrono>
#include <fstream>
#include <thread>
#include <optional>
#include <set>
#include <sstream>

namespace fr {
namespace {

std::filesystem::path reload_plugin(const char* name) {
  return std::filesystem::path(RELOAD_PLUGIN_DIR) / (std::string(name) + PLUGIN_SUFFIX);
}

// Drops `from` into the folder as `name` the way a build or a file manager does: written under
// another name, then renamed into place.
void drop(const std::filesystem::path& from, const std::filesystem::path& folder,
          const std::string& name) {
  const auto tmp = folder / (name + ".partial");
  std::filesystem::copy_file(from, tmp, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::rename(tmp, folder / name);
}

// The library's clock, driven by the test: each poll is one 20 ms frame later. Timings asserted
// against it are the watcher's own (debounce, poll interval), not this machine's load.
struct FrameClock {
  double now_s = 1000;
};

// Polls once per frame until an event of `kind` or `timeout_s` of frames; returns the frame time
// it took, or -1. *message is the event's line.
double poll_until(SceneLibrary& lib, FrameClock& clock, SceneEvent::Kind kind, std::string* message,
                  double timeout_s = 5) {
  const double start = clock.now_s;
  RenderSettings settings;
  for (; clock.now_s - start <= timeout_s; clock.now_s += 0.02)
    for (const SceneEvent& e : lib.poll(clock.now_s, settings)) {
      log_scene_event(e);  // as the explorer does
      if (e.kind == kind) {
        *message = e.to_string();
        return clock.now_s - start;
      }
    }
  return -1;
}

TEST(HotReload, AddChangeBreakRemove) {
  std::ostringstream log;  // the explorer's stderr
  std::optional<LogSession> session(std::in_place, log, LogOptions{});
  const auto folder = test::fresh_dir("hot_reload");
  std::vector<SceneEvent> events;
  SceneLibrary lib({folder}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
  EXPECT_TRUE(lib.slots().empty());
  FrameClock clock;
  std::string m;

  drop(reload_plugin("reload_a"), folder, "probe" PLUGIN_SUFFIX);
  const double appeared_s = poll_until(lib, clock, SceneEvent::Kind::Added, &m);
  ASSERT_GE(appeared_s, 0) << "the new scene never appeared";
  EXPECT_EQ(m, "added 'reload_probe' from probe" PLUGIN_SUFFIX);
  // Not before the file has been stable for the debounce time (0.3 s), and within 2 s.
  EXPECT_GE(appeared_s, 0.3 - 1e-9);
  EXPECT_LT(appeared_s, 2.0);
  RecordProperty("appeared_after_s", std::to_string(appeared_s));
  ASSERT_EQ(lib.find("reload_probe"), 0);
  // The user has tuned it.
  SceneSlot& slot = lib.slots()[0];
  slot.state.params[slot.scene->info.find_param("radius")].v[0] = 1.8;
  slot.state.camera.eye[0] = 0.25;

  drop(reload_plugin("reload_b"), folder, "probe" PLUGIN_SUFFIX);
  ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Reloaded, &m), 0) << "said:\n" << log.str();
  EXPECT_EQ(m, "reloaded 'reload_probe' from probe" PLUGIN_SUFFIX);
  {
    SceneSlot& b = lib.slots()[0];
    EXPECT_EQ(b.scene->info.version, "2.0.0");
    EXPECT_EQ(b.state.params[b.scene->info.find_param("radius")].v[0], 1.5)
        << "kept by key, clamped to B's range";
    EXPECT_EQ(b.state.params[b.scene->info.find_param("tint")].v[0], 0.25) << "new key: default";
    EXPECT_EQ(b.scene->info.find_param("detail"), -1) << "dropped key";
    EXPECT_EQ(b.state.camera.eye[0], 0.25) << "the camera stays";
  }

  drop(reload_plugin("reload_broken"), folder, "probe" PLUGIN_SUFFIX);
  ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Kept, &m), 0);
  EXPECT_EQ(m.rfind("kept the running 'reload_probe': ", 0), 0u) << m;
  EXPECT_NE(m.find("missing_radius"), std::string::npos) << m;
  EXPECT_EQ(lib.slots()[0].scene->info.version, "2.0.0") << "the old build keeps running";
  EXPECT_NE(lib.slots()[0].error.find("reload_broken.cl:2:"), std::string::npos)
      << lib.slots()[0].error;

  std::ofstream(folder / "junk" PLUGIN_SUFFIX) << "not a plugin";
  ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Skipped, &m), 0);
  const bool windows = std::filesystem::path::preferred_separator == '\\';
  EXPECT_NE(m.find(windows ? "not a Windows DLL" : "not an ELF"), std::string::npos) << m;

  std::filesystem::remove(folder / "probe" PLUGIN_SUFFIX);
  ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Removed, &m), 0);
  EXPECT_EQ(m.rfind("'reload_probe' was removed", 0), 0u) << m;
  ASSERT_EQ(lib.slots().size(), 1u) << "a removed scene keeps running";
  EXPECT_TRUE(lib.slots()[0].removed);
  lib.drop_if_removed(0);
  EXPECT_TRUE(lib.slots().empty());
  // Each event was said as it happened, failures as warnings, and the overlay has the same.
  const auto recent = recent_log_messages(64);
  ASSERT_FALSE(recent.empty());
  EXPECT_EQ(recent.back().rfind("'reload_probe' was removed", 0), 0u) << recent.back();
  session.reset();
  const std::string said = log.str();
  EXPECT_NE(said.find("fractalis: added 'reload_probe' from probe" PLUGIN_SUFFIX "\n"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("fractalis: reloaded 'reload_probe' from probe" PLUGIN_SUFFIX "\n"),
            std::string::npos);
  EXPECT_NE(said.find("fractalis: warning: kept the running 'reload_probe': "), std::string::npos);
  EXPECT_NE(said.find("fractalis: warning: skipped "), std::string::npos);
  EXPECT_NE(said.find("fractalis: 'reload_probe' was removed"), std::string::npos);
}

#ifndef _WIN32  // /proc: open files, threads, mappings, children and zombies
size_t count_entries(const char* dir) {
  return static_cast<size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

size_t mapped_copies(const std::string& name_part) {
  std::ifstream maps("/proc/self/maps");
  std::set<std::string> files;
  std::string line;
  while (std::getline(maps, line))
    if (line.find(name_part) != std::string::npos) files.insert(line.substr(line.find('/')));
  return files.size();
}

// Processes this process started and has not reaped, and how many of them are zombies.
std::pair<size_t, size_t> children_and_zombies() {
  size_t children = 0, zombies = 0;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream in(task.path() / "children");
    std::string pid;
    while (in >> pid) {
      ++children;
      std::ifstream stat("/proc/" + pid + "/stat");
      std::string line;
      std::getline(stat, line);
      const size_t paren = line.rfind(')');
      if (paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] == 'Z')
        ++zombies;
    }
  }
  return {children, zombies};
}

size_t mapping_count() {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  size_t n = 0;
  while (std::getline(maps, line)) ++n;
  return n;
}

// Hot reloads of a scene with an update callback, alternating two builds (100 in the suite, a
// thousand under the soak label: test::soak_rounds): no growth in open files, threads, mappings
// or processes, no zombies, and the plugin never mapped here.
TEST(HotReload, ReloadsLeakNothing) {
  const auto folder = test::fresh_dir("hot_reload_soak");
  drop(reload_plugin("reload_a"), folder, "soak_probe" PLUGIN_SUFFIX);
  std::vector<SceneEvent> events;
  SceneLibrary lib({folder}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
  ASSERT_EQ(lib.slots().size(), 1u);
  FrameClock clock;
  std::string m;
  // One reload first, so that the kernels of both versions are built, cached and vetted.
  drop(reload_plugin("reload_b"), folder, "soak_probe" PLUGIN_SUFFIX);
  ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Reloaded, &m), 0) << m;
  drop(reload_plugin("reload_a"), folder, "soak_probe" PLUGIN_SUFFIX);
  ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Reloaded, &m), 0) << m;
  const size_t fds = count_entries("/proc/self/fd"), threads = count_entries("/proc/self/task"),
               maps = mapping_count();
  const auto [children, zombies] = children_and_zombies();
  EXPECT_EQ(zombies, 0u);
  const int reloads = test::soak_rounds(100);
  for (int i = 0; i < reloads; ++i) {
    drop(reload_plugin(i % 2 ? "reload_a" : "reload_b"), folder, "soak_probe" PLUGIN_SUFFIX);
    ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Reloaded, &m), 0)
        << "reload " << i << ": " << m;
    std::string error;
    ASSERT_TRUE(lib.slots()[0].instance->update(lib.slots()[0].state, clock.now_s, &error))
        << error;
  }
  EXPECT_EQ(lib.slots()[0].scene->info.version, "1.0.0");
  EXPECT_LE(count_entries("/proc/self/fd"), fds) << "open files grew over " << reloads << " reloads";
  EXPECT_LE(count_entries("/proc/self/task"), threads) << "threads grew over " << reloads << " reloads";
  // The allocator (and ASan's quarantine, in the sanitizer build) may map a few more regions; a
  // mapping kept per reload would be one a reload, 100 or more.
  EXPECT_LE(mapping_count(), maps + 16) << "mappings grew over " << reloads << " reloads";
  const auto [children_after, zombies_after] = children_and_zombies();
  EXPECT_EQ(children_after, children) << "scene-host processes grew over " << reloads << " reloads";
  EXPECT_EQ(zombies_after, 0u);
  EXPECT_EQ(mapped_copies("soak_probe" PLUGIN_SUFFIX), 0u)
      << "plugin code was mapped into the host";
  EXPECT_EQ(mapped_copies("fractalis-plugin"), 0u) << "plugin code was mapped into the host";
}
#endif

// Scenes found at start are vetted too: a DE that never returns is skipped with the reason, and
// the scene beside it is there.
TEST(HotReload, StartupVetsEveryScene) {
  const auto folder = test::fresh_dir("startup_vet");
  drop(reload_plugin("reload_a"), folder, "good" PLUGIN_SUFFIX);
  drop(std::filesystem::path(HOSTILE_PLUGIN_DIR) / "hostile_de_loop" PLUGIN_SUFFIX, folder,
       "loops" PLUGIN_SUFFIX);
  PluginPolicy policy;
  policy.vet_timeout_s = 8;
  std::vector<SceneEvent> events;
  SceneLibrary lib({folder}, policy, RenderSettings{}, test::worker(), &events);
  ASSERT_EQ(lib.slots().size(), 1u);
  EXPECT_EQ(lib.slots()[0].scene->info.id, "reload_probe");
  // The good scene is added; the looping one is skipped, with why.
  ASSERT_EQ(events.size(), 2u);
  const SceneEvent& skipped = events[0].kind == SceneEvent::Kind::Skipped ? events[0] : events[1];
  EXPECT_EQ(skipped.kind, SceneEvent::Kind::Skipped);
  EXPECT_EQ(skipped.file, folder / "loops" PLUGIN_SUFFIX);
  EXPECT_NE(skipped.to_string().find("skipped " + (folder / "loops" PLUGIN_SUFFIX).string() +
                                     ": a test render at 8x8 did not finish within 8 s"),
            std::string::npos)
      << skipped.to_string();
}

// The explorer's first start: the library returns at once and vets in the background. Nothing
// renders or probes a scene before its test render passed; the one the user waits for is vetted
// first; a DE that never returns becomes a refused slot with why, the others usable; and a
// library destroyed while a test render is under way ends it instead of waiting for its limit.
TEST(HotReload, StartupVetsInTheBackground) {
  const auto folder = test::fresh_dir("startup_vet_background");
  drop(reload_plugin("reload_a"), folder, "good" PLUGIN_SUFFIX);
  drop(std::filesystem::path(HOSTILE_PLUGIN_DIR) / "hostile_de_loop" PLUGIN_SUFFIX, folder,
       "loops" PLUGIN_SUFFIX);
  PluginPolicy policy;
  policy.vet_timeout_s = 8;  // (the good scene's test render must fit, under ASan too)
  std::vector<SceneEvent> events;
  SceneLibrary lib({folder}, policy, RenderSettings{}, test::worker(), &events,
                   /*vet_in_background=*/true);
  ASSERT_EQ(lib.slots().size(), 2u) << "both scenes are listed before their test renders end";
  const int loops = lib.find("fixture_de_loop"), good = lib.find("reload_probe");
  ASSERT_GE(loops, 0);
  ASSERT_GE(good, 0);
  // (The good scene may be known from an earlier run's markers; the looping one never passes.)
  EXPECT_TRUE(lib.slots()[loops].preparing);
  EXPECT_FALSE(lib.slots()[loops].usable());
  Settings settings;
  settings.render.width_px = 16;
  settings.render.height_px = 16;
  Explorer explorer(settings, test::worker(), lib, "fixture_de_loop");
  FrameClock clock;
  std::vector<SceneEvent> said;
  while (lib.slots()[loops].preparing && clock.now_s < 1000 + 60) {
    explorer.update(InputState{}, 0.02, clock.now_s);  // polls the library, as the loop does
    EXPECT_EQ(explorer.render(16, 16), nullptr) << "a scene being prepared is never rendered";
    clock.now_s += 0.02;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_FALSE(lib.slots()[loops].preparing) << "its test render never ended";
  EXPECT_TRUE(lib.slots()[loops].refused);
  EXPECT_NE(lib.slots()[loops].error.find("did not finish within 8 s"), std::string::npos)
      << lib.slots()[loops].error;
  EXPECT_EQ(explorer.render(16, 16), nullptr) << "a refused scene is never rendered";
  EXPECT_EQ(explorer.frames_rendered(), 0u);
  // The good one, once its own test render is in, renders.
  explorer.select_scene(good);
  const FrameView* frame = nullptr;
  for (int i = 0; i < 3000 && !frame; ++i) {
    explorer.update(InputState{}, 0.02, clock.now_s += 0.02);
    frame = explorer.render(16, 16);
    if (!frame) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_NE(frame, nullptr);
  EXPECT_TRUE(lib.slots()[good].usable());

  // Quitting during a long test render: the child is ended, not waited for.
  policy.vet_timeout_s = 120;
  const auto started = std::chrono::steady_clock::now();
  {
    std::vector<SceneEvent> more;
    SceneLibrary quitting({folder}, policy, RenderSettings{}, test::worker(), &more, true);
    EXPECT_TRUE(quitting.slots()[quitting.find("fixture_de_loop")].preparing);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 60)
      << "the library waited for the test render's 120 s limit";
}

// Every hostile fixture dropped over a running scene: the old build keeps running, with the
// reason kept, and it still updates and renders afterwards.
TEST(HotReload, HostileBuildsNeverReplaceTheRunningScene) {
  const auto folder = test::fresh_dir("hot_reload_hostile");
  drop(reload_plugin("reload_a"), folder, "probe" PLUGIN_SUFFIX);
  std::filesystem::copy_file(test::fixture_plugin("valid_scene"), folder / "other" PLUGIN_SUFFIX);
  std::vector<SceneEvent> events;
  PluginPolicy policy;
  policy.load_timeout_s = 2;
  policy.call_timeout_s = 0.5;
  policy.vet_timeout_s = 8;
  SceneLibrary lib({folder}, policy, RenderSettings{}, test::worker(), &events);
  ASSERT_EQ(lib.slots().size(), 2u);
  FrameClock clock;
  std::string m;
  // (Windows: abort() exits with status 3; a fault is an access violation.)
  const bool windows = std::filesystem::path::preferred_separator == '\\';
  const char* const crashed = windows ? "crashed (access violation)" : "crashed (SIG";
  const std::pair<const char*, const char*> cases[] = {
      {"ctor_abort", windows ? "exited with status 3" : "crashed (SIGABRT"},
      {"ctor_loop", "did not answer within 2 s"},
      {"create_crash", crashed},
      {"create_hang", "did not answer within 0.5 s"},
      {"create_throw", "create threw a C++ exception"},
      {"update_crash", crashed},
      {"update_throw", "update threw a C++ exception"},
      {"update_exit", "exited with status 0"},
      {"update_bad_camera", "update left an invalid camera"},
      {"absurd_counts", "param_count 2000000000 is more than 256"},
      {"escape_name", "control character 0x1b"},
      {"missing_dep", "libfixture_missing_dep_lib" PLUGIN_SUFFIX},
      {"de_loop", "did not finish within 8 s (plugins.vet_timeout_s)"},
  };
  for (const auto& [fixture, reason] : cases) {
    SCOPED_TRACE(fixture);
    drop(std::filesystem::path(HOSTILE_PLUGIN_DIR) /
             ("hostile_" + std::string(fixture) + PLUGIN_SUFFIX),
         folder, "probe" PLUGIN_SUFFIX);
    ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Kept, &m, 30), 0);
    EXPECT_EQ(m.rfind("kept the running 'reload_probe': ", 0), 0u) << m;
    EXPECT_NE(m.find(reason), std::string::npos) << m;
    const int index = lib.find("reload_probe");
    ASSERT_GE(index, 0);
    EXPECT_EQ(lib.slots()[index].scene->info.version, "1.0.0");
    std::string error;
    EXPECT_TRUE(lib.slots()[index].instance->update(lib.slots()[index].state, 0, &error)) << error;
  }
  // A file that suddenly declares another file's scene id is refused, and both keep running.
  drop(reload_plugin("reload_a"), folder, "other" PLUGIN_SUFFIX);
  ASSERT_GE(poll_until(lib, clock, SceneEvent::Kind::Kept, &m), 0);
  EXPECT_EQ(m.rfind("kept the running 'fixture_valid': ", 0), 0u) << m;
  EXPECT_NE(m.find("declares scene id 'reload_probe', which probe" PLUGIN_SUFFIX " provides"),
            std::string::npos)
      << m;
  ASSERT_EQ(lib.slots().size(), 2u);
  EXPECT_EQ(lib.slots()[lib.find("reload_probe")].scene->file, folder / "probe" PLUGIN_SUFFIX);
  Renderer renderer(test::runtime());
  RenderSettings settings;
  settings.width_px = settings.height_px = 8;
  const SceneSlot& slot = lib.slots()[lib.find("reload_probe")];
  EXPECT_EQ(renderer.render(slot.scene->info, slot.state, settings).rgba8.size(), 8u * 8u * 4u);
}

}  // namespace
}  // namespace fr
