// What the render worker costs a frame: the explorer's calls for one moving frame (the DE at the
// eye; render_frame: a first sample, its display image and steps) through a
// fractalis-render-worker process and in this process (plugins.isolation = "none"), for a view
// that looks away from the scene, so that the device's own work is as small as it gets and the
// difference is the worker's. And what starting a worker costs. Google Benchmark; run
// ./build/tests/render_worker_bench (docs/architecture.md reports its medians).
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_instance.hpp"
#include "render/device.hpp"
#include "worker/render_worker.hpp"
#include "test_paths.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace fr {
namespace {

const LoadedScene& mandelbulb() {
  static const LoadOutcome o =
      load_scene_plugin(std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulb" PLUGIN_SUFFIX);
  if (!o.scene) throw std::runtime_error(o.message);
  return *o.scene;
}

const DeviceInfo& device() {
  static const DeviceInfo d = [] {
    std::string error;
    auto found = select_device(list_devices(), "", &error);
    if (!found) throw std::runtime_error(error);
    return *found;
  }();
  return d;
}

RenderWorkerLimits limits(int64_t isolated) {
  PluginPolicy policy;
  policy.isolation = isolated ? PluginIsolation::Process : PluginIsolation::None;
  return explorer_worker_limits(policy);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// The explorer's calls of one moving frame, in the worker and in process, alternately (the order
// swapped every pair, so that the machine's drift falls on both): each pair's difference is the
// worker's cost for that frame, and its median is the `extra_ms` this reports, besides the
// medians of each (`worker_ms`, `in_process_ms`). The iteration's time is the pair's.
void BM_ExplorerFramePair(benchmark::State& state) {
  const LoadedScene& scene = mandelbulb();
  SceneState scene_state = make_default_state(scene.info);
  scene_state.camera.eye[0] = 0, scene_state.camera.eye[1] = 0, scene_state.camera.eye[2] = 10;
  scene_state.camera.target[0] = 0, scene_state.camera.target[1] = 0;
  scene_state.camera.target[2] = 20;  // looking away: every ray misses the bounding sphere
  RenderSettings settings;
  settings.width_px = static_cast<int>(state.range(0));
  settings.height_px = static_cast<int>(state.range(1));
  RenderWorker isolated(device(), limits(1)), in_process(device(), limits(0));
  const std::vector<std::array<float, 3>> eye = {{0, 0, 10}};
  const auto frame_ms = [&](RenderWorker& worker) {
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(worker.probe_de(scene.info, scene_state.params, eye));
    benchmark::DoNotOptimize(worker.render_frame(scene.info, scene_state, settings, 0,
                                                 Readback::DisplayAndSteps,
                                                 Readback::DisplayAndSteps));
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
  };
  frame_ms(isolated), frame_ms(in_process);  // kernels built, buffers and shared frame sized
  std::vector<double> worker_ms, local_ms, extra_ms;
  bool worker_first = true;
  for (auto _ : state) {
    const double a = worker_first ? frame_ms(isolated) : frame_ms(in_process);
    const double b = worker_first ? frame_ms(in_process) : frame_ms(isolated);
    worker_ms.push_back(worker_first ? a : b);
    local_ms.push_back(worker_first ? b : a);
    extra_ms.push_back(worker_ms.back() - local_ms.back());
    worker_first = !worker_first;
  }
  state.counters["worker_ms"] = median(worker_ms);
  state.counters["in_process_ms"] = median(local_ms);
  state.counters["extra_ms"] = median(extra_ms);
  state.SetLabel(std::to_string(settings.width_px) + "x" + std::to_string(settings.height_px));
}
BENCHMARK(BM_ExplorerFramePair)
    ->Args({1280, 720})
    ->Args({3840, 2160})
    ->Args({8, 8})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

// A fresh worker up to its first answer (the device opened): what a restart after a failure costs.
void BM_WorkerStart(benchmark::State& state) {
  const LoadedScene& scene = mandelbulb();
  const SceneState scene_state = make_default_state(scene.info);
  const std::vector<std::array<float, 3>> eye = {{0, 0, 3}};
  for (auto _ : state) {
    RenderWorker worker(device(), limits(1));
    benchmark::DoNotOptimize(worker.probe_de(scene.info, scene_state.params, eye));
  }
}
BENCHMARK(BM_WorkerStart)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace
}  // namespace fr

BENCHMARK_MAIN();
