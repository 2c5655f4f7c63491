// test_support.hpp — what several tests share: fixture paths and one OpenCL device per process.
#pragma once

#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "plugin/plugin_loader.hpp"
#include "render/cl_runtime.hpp"
#include "render/device.hpp"
#include "test_paths.hpp"
#include "worker/render_worker.hpp"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fr::test {

inline std::filesystem::path fixture_plugin(const std::string& name) {
  return std::filesystem::path(FIXTURE_PLUGIN_DIR) / ("fixture_" + name + PLUGIN_SUFFIX);
}

// A scene that must load: the test fails loudly otherwise.
inline std::shared_ptr<const LoadedScene> load_or_fail(const std::filesystem::path& file) {
  LoadOutcome o = load_scene_plugin(file);
  EXPECT_EQ(o.result, LoadResult::Loaded) << file << ": " << o.message;
  return o.scene;
}

inline std::shared_ptr<const LoadedScene> mandelbulb() {
  return load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulb" PLUGIN_SUFFIX);
}
inline std::shared_ptr<const LoadedScene> unit_ball() {
  return load_or_fail(std::filesystem::path(TEST_SCENE_DIR) / "unit_ball" PLUGIN_SUFFIX);
}
inline std::shared_ptr<const LoadedScene> plain_sponge() {
  return load_or_fail(std::filesystem::path(TEST_SCENE_DIR) / "plain_sponge" PLUGIN_SUFFIX);
}
inline std::shared_ptr<const LoadedScene> material_ball() {
  return load_or_fail(std::filesystem::path(TEST_SCENE_DIR) / "material_ball" PLUGIN_SUFFIX);
}

// The default device (PoCL's CPU device on the development machines), opened once.
inline ClRuntime& runtime() {
  static std::unique_ptr<ClRuntime> rt = [] {
    std::string error;
    auto device = select_device(list_devices(), "", &error);
    if (!device) throw std::runtime_error(error);
    return std::make_unique<ClRuntime>(*device);
  }();
  return *rt;
}

// A render worker (a fractalis-render-worker process) on the same device, started on first use.
inline RenderWorker& worker() {
  static std::unique_ptr<RenderWorker> w = std::make_unique<RenderWorker>(
      runtime().device(), command_worker_limits(PluginPolicy{}, 600));
  return *w;
}

// A file's whole content ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// A fresh, empty folder under the build tree's test output.
inline std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = std::filesystem::path(TEST_OUTPUT_DIR) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A fresh folder `name` holding only the scene plugin `id` of `from` (a library of one scene).
inline std::filesystem::path folder_of_one_scene(const std::string& name,
                                                 const std::filesystem::path& from,
                                                 const std::string& id) {
  auto dir = fresh_dir(name);
  std::filesystem::copy_file(from / (id + PLUGIN_SUFFIX), dir / (id + PLUGIN_SUFFIX));
  return dir;
}

// Pixels (RGBA8, alpha ignored) where some colour channel differs by more than `tolerance` of
// 255. Images of different sizes differ everywhere.
inline size_t pixels_differing(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b,
                               int tolerance) {
  if (a.size() != b.size()) return std::max(a.size(), b.size()) / 4;
  size_t n = 0;
  for (size_t p = 0; p + 3 < a.size(); p += 4)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(a[p + c]) - int(b[p + c])) > tolerance) {
        ++n;
        break;
      }
  return n;
}

struct LoadedPng {
  int width_px = 0, height_px = 0;
  std::vector<uint8_t> rgba8;
};

// A PNG read back as RGBA8; empty (0 x 0) if it cannot be read.
inline LoadedPng load_png(const std::filesystem::path& file) {
  LoadedPng png;
  int channels = 0;
  unsigned char* pixels =
      stbi_load(file.string().c_str(), &png.width_px, &png.height_px, &channels, 4);
  if (!pixels) return {};
  png.rgba8.assign(pixels, pixels + size_t(png.width_px) * png.height_px * 4);
  stbi_image_free(pixels);
  return png;
}

// A program run to its end, as a user's shell would run it: its exit status (-1 when it did not
// exit by itself), how it ended ("exited with status 1", "crashed (...)") and everything it
// wrote to stdout and stderr, interleaved as written.
struct ProgramRun {
  int exit_code = -1;
  std::string how;
  std::string output;
};

// Sets (or, with nullopt, removes) an environment variable of this process.
inline void set_environment(const std::string& name, const std::optional<std::string>& value) {
#ifdef _WIN32
  _putenv_s(name.c_str(), value ? value->c_str() : "");  // "" removes it there
#else
  if (value)
    setenv(name.c_str(), value->c_str(), 1);
  else
    unsetenv(name.c_str());
#endif
}

// How many rounds a soak loop (a thousand worker restarts, a thousand hot reloads) runs: the
// suite runs `suite_rounds`, enough for a per-round leak to pass each check's margin; the `soak`
// CTest label (scripts/soak.sh) sets FRACTALIS_SOAK_ROUNDS to the whole count. A value that is
// not a whole number from 1 to 1000000 fails the test that asked, naming it.
inline int soak_rounds(int suite_rounds) {
  const char* text = std::getenv("FRACTALIS_SOAK_ROUNDS");
  if (!text) return suite_rounds;
  char* end = nullptr;
  const long rounds = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || rounds < 1 || rounds > 1000000) {
    ADD_FAILURE() << "FRACTALIS_SOAK_ROUNDS='" << text << "': expected a whole number from 1 to "
                  << "1000000; running " << suite_rounds << " rounds";
    return suite_rounds;
  }
  return static_cast<int>(rounds);
}

using Environment = std::vector<std::pair<std::string, std::string>>;

// Runs `program` with `arguments` through the platform layer's child processes (the same code on
// Linux and Windows, no shell in between), with `environment` added to ours for it alone,
// killing it after `timeout_s`.
inline ProgramRun run_program(const std::filesystem::path& program,
                              const std::vector<std::string>& arguments,
                              const Environment& environment = {}, double timeout_s = 600) {
  ProgramRun run;
  ChannelPair pipe;
  std::string error;
  if (!make_pipe(&pipe, &error)) {
    run.how = "no pipe: " + error;
    return run;
  }
  ChildSpec spec;
  spec.program = program;
  spec.arguments = arguments;
  spec.stdout_to = pipe.theirs.handle();
  spec.stderr_to = pipe.theirs.handle();
  // A child takes our environment when it starts: set around the start, then put back.
  std::vector<std::optional<std::string>> before;
  for (const auto& [name, value] : environment) {
    const char* was = std::getenv(name.c_str());
    before.push_back(was ? std::optional<std::string>(was) : std::nullopt);
    set_environment(name, value);
  }
  auto child = ChildProcess::start(spec, &error);
  for (size_t i = environment.size(); i-- > 0;)  // backwards: a name given twice ends as it was
    set_environment(environment[i].first, before[i]);
  pipe.theirs.close();  // the child's copy alone keeps the pipe open
  if (!child) {
    run.how = "could not be started: " + error;
    return run;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  char buffer[4096];
  for (;;) {
    const auto left_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                             deadline - std::chrono::steady_clock::now())
                             .count();
    size_t got = 0;
    const ChannelStatus status =
        pipe.ours.read_some(buffer, sizeof buffer, int(std::max<int64_t>(left_ms, 0)), &got);
    if (status == ChannelStatus::Ok) {
      run.output.append(buffer, got);
      continue;
    }
    if (status == ChannelStatus::TimedOut) {
      child->kill();
      run.output += "\n[test: killed after " + std::to_string(timeout_s) + " s]\n";
    }
    break;
  }
  // The pipe closed (or failed): the child is ending; still never waited on past the deadline.
  const auto left_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                           deadline - std::chrono::steady_clock::now())
                           .count();
  if (!child->wait(int(std::max<int64_t>(left_ms, 0)))) child->kill();
  run.how = child->how_it_ended();
  run.exit_code = child->exit_status();
  return run;
}

// `fractalis` (the build tree's) with `arguments`.
inline ProgramRun run_fractalis(const std::vector<std::string>& arguments,
                                const Environment& environment = {}) {
  return run_program(FRACTALIS_EXECUTABLE, arguments, environment);
}

}  // namespace fr::test
