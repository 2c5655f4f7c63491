// What the render worker costs a frame: the explorer's per-frame calls (the DE at the eye, one
// sample, the display image read back) through a fractalis-render-worker process and in this
// process (plugins.isolation = "none"), for a view that looks away from the scene, so that the
// device's own work is as small as it gets and the difference is the worker's. And what starting
// a worker costs. Google Benchmark; run ./build/tests/render_worker_bench (README reports its
// medians).
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_instance.hpp"
#include "render/device.hpp"
#include "worker/render_worker.hpp"

#include <benchmark/benchmark.h>

#include <stdexcept>

namespace fr {
namespace {

const LoadedScene& mandelbulb() {
  static const LoadOutcome o =
      load_scene_plugin(std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulb.so");
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

void BM_ExplorerFrameCalls(benchmark::State& state) {
  const LoadedScene& scene = mandelbulb();
  SceneState scene_state = make_default_state(scene.info);
  scene_state.camera.eye[0] = 0, scene_state.camera.eye[1] = 0, scene_state.camera.eye[2] = 10;
  scene_state.camera.target[0] = 0, scene_state.camera.target[1] = 0;
  scene_state.camera.target[2] = 20;  // looking away: every ray misses the bounding sphere
  RenderSettings settings;
  settings.width_px = static_cast<int>(state.range(1));
  settings.height_px = static_cast<int>(state.range(2));
  RenderWorker worker(device(), limits(state.range(0)));
  FrameImage image;
  const std::vector<std::array<float, 3>> eye = {{0, 0, 10}};
  for (auto _ : state) {
    benchmark::DoNotOptimize(worker.probe_de(scene.info, scene_state.params, eye));
    worker.render_sample(scene.info, scene_state, settings, 0, Readback::DisplayAndSteps);
    worker.finish(settings, Readback::Display, image);
  }
  state.SetLabel(std::string(state.range(0) ? "render worker" : "in-process") + " " +
                 std::to_string(settings.width_px) + "x" + std::to_string(settings.height_px));
}
BENCHMARK(BM_ExplorerFrameCalls)
    ->Args({1, 1280, 720})
    ->Args({0, 1280, 720})
    ->Args({1, 3840, 2160})
    ->Args({0, 3840, 2160})
    ->Args({1, 8, 8})
    ->Args({0, 8, 8})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
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
