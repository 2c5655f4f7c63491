// Hot reload, against a running scene library (the explorer's, headless): the test copies new,
// changed, broken and removed plugins into its folder and polls like the explorer's frame loop.
// Checks: a new scene appears within 2 s of the poll's own clock (after the debounce time); a
// changed one reloads keeping parameter values by key; a broken build leaves the old one running
// with the error kept; a removed one keeps running; and 50 reloads grow neither open files nor
// threads, and leave one copy of the library mapped.
#include "app/scene_library.hpp"
#include "test_support.hpp"

#include <fstream>
#include <set>

namespace fr {
namespace {

std::filesystem::path reload_plugin(const char* name) {
  return std::filesystem::path(RELOAD_PLUGIN_DIR) / (std::string(name) + ".so");
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

// Polls once per frame until a message starting with `prefix` or `timeout_s` of frames; returns
// the frame time it took, or -1.
double poll_until(SceneLibrary& lib, FrameClock& clock, const std::string& prefix,
                  std::string* message, double timeout_s = 5) {
  const double start = clock.now_s;
  RenderSettings settings;
  for (; clock.now_s - start <= timeout_s; clock.now_s += 0.02)
    for (const auto& m : lib.poll(clock.now_s, settings))
      if (m.rfind(prefix, 0) == 0) {
        *message = m;
        return clock.now_s - start;
      }
  return -1;
}

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

TEST(HotReload, AddChangeBreakRemove) {
  const auto folder = test::fresh_dir("hot_reload");
  std::vector<std::string> messages;
  SceneLibrary lib({folder}, test::runtime(), &messages);
  EXPECT_TRUE(lib.slots().empty());
  FrameClock clock;
  std::string m;

  drop(reload_plugin("reload_a"), folder, "probe.so");
  const double appeared_s = poll_until(lib, clock, "added 'reload_probe'", &m);
  ASSERT_GE(appeared_s, 0) << "the new scene never appeared";
  // Not before the file has been stable for the debounce time (0.3 s), and within 2 s.
  EXPECT_GE(appeared_s, 0.3 - 1e-9);
  EXPECT_LT(appeared_s, 2.0);
  RecordProperty("appeared_after_s", std::to_string(appeared_s));
  ASSERT_EQ(lib.find("reload_probe"), 0);
  // The user has tuned it.
  SceneSlot& slot = lib.slots()[0];
  slot.state.params[slot.scene->info.find_param("radius")].v[0] = 1.8;
  slot.state.camera.eye[0] = 0.25;

  drop(reload_plugin("reload_b"), folder, "probe.so");
  ASSERT_GE(poll_until(lib, clock, "reloaded 'reload_probe'", &m), 0);
  {
    SceneSlot& b = lib.slots()[0];
    EXPECT_EQ(b.scene->info.version, "2.0.0");
    EXPECT_EQ(b.state.params[b.scene->info.find_param("radius")].v[0], 1.5)
        << "kept by key, clamped to B's range";
    EXPECT_EQ(b.state.params[b.scene->info.find_param("tint")].v[0], 0.25) << "new key: default";
    EXPECT_EQ(b.scene->info.find_param("detail"), -1) << "dropped key";
    EXPECT_EQ(b.state.camera.eye[0], 0.25) << "the camera stays";
  }

  drop(reload_plugin("reload_broken"), folder, "probe.so");
  ASSERT_GE(poll_until(lib, clock, "kept the running 'reload_probe'", &m), 0);
  EXPECT_NE(m.find("missing_radius"), std::string::npos) << m;
  EXPECT_EQ(lib.slots()[0].scene->info.version, "2.0.0") << "the old build keeps running";
  EXPECT_NE(lib.slots()[0].error.find("reload_broken.cl:2:"), std::string::npos)
      << lib.slots()[0].error;

  std::ofstream(folder / "junk.so") << "not a plugin";
  ASSERT_GE(poll_until(lib, clock, "skipped", &m), 0);
  EXPECT_NE(m.find("not an ELF"), std::string::npos) << m;

  std::filesystem::remove(folder / "probe.so");
  ASSERT_GE(poll_until(lib, clock, "'reload_probe' was removed", &m), 0);
  ASSERT_EQ(lib.slots().size(), 1u) << "a removed scene keeps running";
  EXPECT_TRUE(lib.slots()[0].removed);
  lib.drop_if_removed(0);
  EXPECT_TRUE(lib.slots().empty());
}

TEST(HotReload, FiftyReloadsLeakNothing) {
  const auto folder = test::fresh_dir("hot_reload_soak");
  drop(reload_plugin("reload_a"), folder, "soak_probe.so");
  std::vector<std::string> messages;
  SceneLibrary lib({folder}, test::runtime(), &messages);
  ASSERT_EQ(lib.slots().size(), 1u);
  FrameClock clock;
  std::string m;
  // One reload first, so that the kernels of both versions are built and cached.
  drop(reload_plugin("reload_b"), folder, "soak_probe.so");
  ASSERT_GE(poll_until(lib, clock, "reloaded", &m), 0);
  const size_t fds = count_entries("/proc/self/fd"), threads = count_entries("/proc/self/task");
  for (int i = 0; i < 50; ++i) {
    drop(reload_plugin(i % 2 ? "reload_b" : "reload_a"), folder, "soak_probe.so");
    ASSERT_GE(poll_until(lib, clock, "reloaded", &m), 0) << "reload " << i;
  }
  EXPECT_EQ(lib.slots()[0].scene->info.version, "2.0.0");
  EXPECT_LE(count_entries("/proc/self/fd"), fds) << "open files grew over 50 reloads";
  EXPECT_LE(count_entries("/proc/self/task"), threads) << "threads grew over 50 reloads";
  EXPECT_EQ(mapped_copies("soak_probe.so"), 1u) << "old copies of the library are still mapped";
}

}  // namespace
}  // namespace fr
