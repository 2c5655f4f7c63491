// Edit mode's loop, timed as an author feels it (app/scene_edit.hpp): from saving a file of a
// project `fractalis new` made to the first frame that shows the change. A .cl save (a constant
// no run used before, so every save compiles anew: no kernel cache helps; its first frame is the
// quick build's, and the counter optimized_frame_s says when the optimized build's frame
// followed) and a .c save (a rebuilt plugin, installed and reloaded by the scene library). Medians
// over the iterations:
//   ./build/tests/edit_bench --benchmark_repetitions=1
#include "app/explorer.hpp"
#include "app/scene_edit.hpp"
#include "cli/cli.hpp"
#include "io/run_program.hpp"
#include "render/device.hpp"
#include "platform/user_folders.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

namespace fr {
namespace {

using Clock = std::chrono::steady_clock;

// A scene project made by `fractalis new NAME [--from FROM]`, explored in edit mode.
struct EditSession {
  std::string name;
  std::filesystem::path root, dir;
  std::unique_ptr<RenderWorker> worker;
  std::unique_ptr<SceneLibrary> library;
  std::unique_ptr<Explorer> explorer;
  std::unique_ptr<SceneEdit> edit;
  std::vector<SceneEvent> events;
  InputState input;
  Clock::time_point start = Clock::now();
  std::string cl, c;

  EditSession(const std::string& project_name, const std::string& from)
      : name(project_name),
        root(std::filesystem::temp_directory_path() / "fractalis_edit_bench" / project_name),
        dir(root / project_name) {
    std::filesystem::remove_all(root);
    set_environment_variable("XDG_DATA_HOME", root / "data");
    std::vector<std::string> args = {"new", name, "--dir", dir.string()};
    if (!from.empty()) args.insert(args.end(), {"--from", from});
    std::ostringstream out, err;
    if (run_cli(args, out, err) != 0)
      throw std::runtime_error("fractalis new failed: " + err.str());
    std::string error;
    const auto project = read_scene_project(dir, &error);
    if (!project) throw std::runtime_error(error);
    const auto device = select_device(list_devices(), "", &error);
    if (!device) throw std::runtime_error(error);
    worker = std::make_unique<RenderWorker>(*device, explorer_worker_limits({}));
    library = std::make_unique<SceneLibrary>(
        std::vector<std::filesystem::path>{root / "data" / "fractalis" / "scenes"},
        PluginPolicy{}, RenderSettings{}, *worker, &events);
    explorer = std::make_unique<Explorer>(Settings{}, *worker, *library, name);
    edit = std::make_unique<SceneEdit>(*project, find_program_on_path("cmake"));
    cl = read(dir / (name + ".cl"));
    c = read(dir / (name + ".c"));
    frames_until([&] { return explorer->frames_rendered() > 3; });
  }
  static std::string read(const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  double now_s() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
  // Its data folder is the one a C build installs into and the library watches (each session
  // has its own; the environment is the process's).
  void make_current() const { set_environment_variable("XDG_DATA_HOME", root / "data"); }
  // The explorer's loop at a 1280x720 window (it renders at the resolution its frame rate allows).
  // Returns the longest turn of the loop, seconds: how long the window went without answering.
  double frames_until(const std::function<bool()>& done) {
    double longest_s = 0;
    for (int i = 0; i < 100000 && !done(); ++i) {
      const auto turn = Clock::now();
      explorer->update(input, 1.0 / 30, now_s());
      edit->poll(*explorer, now_s());
      explorer->render(1280, 720);
      input.end_frame();
      longest_s = std::max(longest_s, std::chrono::duration<double>(Clock::now() - turn).count());
    }
    return longest_s;
  }
};

// The template (a rippled sphere), and the Mandelbulb (a heavier DE and kernel).
EditSession& template_session() {
  static EditSession s("bench_blob", "");
  return s;
}
EditSession& mandelbulb_session() {
  static EditSession s("bench_bulb", "mandelbulb");
  return s;
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no '" + from + "'");
  return text.replace(at, from.size(), to);
}

// A constant no earlier run used (PoCL's kernel cache on disk outlives the process): the time
// since the epoch in microseconds, as a float literal with all its digits.
std::string fresh_constant() {
  const auto us = std::chrono::duration_cast<std::chrono::microseconds>(
                      std::chrono::system_clock::now().time_since_epoch())
                      .count();
  std::ostringstream text;
  text << "1.0f + " << (us % 1000000000) << ".0e-15f";
  return text.str();
}

// First, while the template's session is the only one: a second session's scene library in the
// same process slows the first's reload of a rebuilt plugin (both watch for plugins).
void SaveCToNewFrame(benchmark::State& state) {
  EditSession& s = template_session();
  s.make_current();
  int n = 0;
  for (auto _ : state) {
    const std::string marker = "Edit " + std::to_string(++n) + ":";
    const auto t0 = Clock::now();
    const uint64_t frames = s.explorer->frames_rendered();
    std::ofstream(s.dir / (s.name + ".c"), std::ios::trunc)
        << with(s.c, "A rippled sphere", marker + " a rippled sphere");
    s.frames_until([&] {
      return (s.explorer->current().scene->info.description.rfind(marker, 0) == 0 &&
              s.explorer->frames_rendered() > frames) ||
             s.edit->failed();
    });
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - t0).count());
    if (s.edit->failed()) state.SkipWithError(s.edit->status().c_str());
  }
}
BENCHMARK(SaveCToNewFrame)->UseManualTime()->Iterations(5)->Unit(benchmark::kMillisecond);

// Saves `change(constant)` in place of `anchor` in the project's .cl, a new constant each time.
void SaveOpenCLToNewFrame(benchmark::State& state, EditSession& s, const std::string& anchor,
                          const std::function<std::string(const std::string&)>& change) {
  s.make_current();
  double optimized_s = 0;
  std::vector<double> longest_turns_s;  // by save
  for (auto _ : state) {
    const int applied = s.edit->opencl_applied();
    const std::string constant = fresh_constant();
    const auto t0 = Clock::now();
    std::ofstream(s.dir / (s.name + ".cl"), std::ios::trunc) << with(s.cl, anchor, change(constant));
    // On screen: the first frame rendered with the new DE (the quick build's), the moment
    // render() returns it (the window presents it then).
    for (int i = 0; i < 100000 && !s.edit->failed(); ++i) {
      s.explorer->update(s.input, 1.0 / 30, s.now_s());
      s.edit->poll(*s.explorer, s.now_s());
      const bool new_de =
          s.explorer->current().scene->info.de_source.find(constant) != std::string::npos;
      const uint64_t frames = s.explorer->frames_rendered();
      s.explorer->render(1280, 720);
      s.input.end_frame();
      if (new_de && s.explorer->frames_rendered() > frames) break;
    }
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - t0).count());
    if (s.edit->failed()) state.SkipWithError(s.edit->status().c_str());
    // Then the optimized build's frame, timed as a counter, before the next save; and the
    // longest the loop went without answering meanwhile (its builds happen in the background:
    // app/kernel_warmup.hpp).
    longest_turns_s.push_back(s.frames_until(
        [&] { return s.edit->opencl_applied() > applied || s.edit->failed(); }));
    optimized_s += std::chrono::duration<double>(Clock::now() - t0).count();
  }
  state.counters["optimized_frame_s"] =
      benchmark::Counter(optimized_s, benchmark::Counter::kAvgIterations);
  std::sort(longest_turns_s.begin(), longest_turns_s.end());
  if (!longest_turns_s.empty()) {
    state.counters["longest_turn_median_s"] = longest_turns_s[longest_turns_s.size() / 2];
    state.counters["longest_turn_max_s"] = longest_turns_s.back();
  }
}
void SaveOpenCLToNewFrame_Template(benchmark::State& state) {
  SaveOpenCLToNewFrame(state, template_session(), "r - PARAM(radius)",
                       [](const std::string& k) { return "r - (" + k + ") * PARAM(radius)"; });
}
BENCHMARK(SaveOpenCLToNewFrame_Template)->UseManualTime()->Iterations(7)->Unit(benchmark::kMillisecond);
void SaveOpenCLToNewFrame_Mandelbulb(benchmark::State& state) {
  SaveOpenCLToNewFrame(state, mandelbulb_session(), "de_mandelbulb(p, PARAM(power),",
                       [](const std::string& k) {
                         return "de_mandelbulb(p, (" + k + ") * PARAM(power),";
                       });
}
BENCHMARK(SaveOpenCLToNewFrame_Mandelbulb)
    ->UseManualTime()
    ->Iterations(7)
    ->Unit(benchmark::kMillisecond);


}  // namespace
}  // namespace fr

BENCHMARK_MAIN();
