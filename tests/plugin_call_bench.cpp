// What isolation costs: one update call of a scene, through a scene-host process (the default)
// and in-process (plugins.isolation = "none"), and loading a plugin either way. Google
// Benchmark; run ./build/tests/plugin_call_bench (docs/architecture.md reports its medians).
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_instance.hpp"
#include "test_paths.hpp"

#include <benchmark/benchmark.h>

#include <stdexcept>

namespace fr {
namespace {

std::filesystem::path mandelbulb_file() {
  return std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulb" PLUGIN_SUFFIX;
}

PluginPolicy policy_for(int64_t isolated) {
  PluginPolicy p;
  p.isolation = isolated ? PluginIsolation::Process : PluginIsolation::None;
  return p;
}

// One update of Mandelbulb (its callback animates the power from the time): the round trip
// that happens once per explorer frame.
void BM_Update(benchmark::State& state) {
  const LoadOutcome o = load_scene_plugin(mandelbulb_file(), policy_for(state.range(0)));
  if (!o.scene) throw std::runtime_error(o.message);
  std::string error;
  auto instance = SceneInstance::create(o.scene, &error);
  if (!instance) throw std::runtime_error(error);
  SceneState scene_state = make_default_state(o.scene->info);
  double t = 0;
  for (auto _ : state) {
    if (!instance->update(scene_state, t, &error)) throw std::runtime_error(error);
    t += 1.0 / 60;
  }
  state.SetLabel(state.range(0) ? "scene-host process" : "in-process");
}
BENCHMARK(BM_Update)->Arg(1)->Arg(0)->Repetitions(5)->ReportAggregatesOnly(true);

// Loading and checking a plugin, creating an instance and the first update: what a hot reload
// costs before its kernel is built.
void BM_LoadCreateUpdate(benchmark::State& state) {
  for (auto _ : state) {
    const LoadOutcome o = load_scene_plugin(mandelbulb_file(), policy_for(state.range(0)));
    std::string error;
    auto instance = SceneInstance::create(o.scene, &error);
    SceneState scene_state = make_default_state(o.scene->info);
    if (!instance || !instance->update(scene_state, 0, &error)) throw std::runtime_error(error);
  }
  state.SetLabel(state.range(0) ? "scene-host process" : "in-process");
}
BENCHMARK(BM_LoadCreateUpdate)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace
}  // namespace fr

BENCHMARK_MAIN();
