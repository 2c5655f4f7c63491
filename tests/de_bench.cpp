// The DE library's cost per evaluation: each in-tree scene's own OpenCL DE evaluated at 65536
// points through the probe kernel (render/de_probe.hpp), in float and double, at the device's
// lane width. Google Benchmark; run ./build/tests/de_bench. The figure is DE evaluations per
// second (items_per_second, by wall-clock time), upload and read-back included: what one march
// step of every pixel of a 256x256 image costs. Points outside the surface's reach escape in a
// few iterations, as most of a march's evaluations do.
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_instance.hpp"
#include "render/de_probe.hpp"
#include "render/device.hpp"
#include "test_paths.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace fr {
namespace {

ClRuntime& runtime() {
  static std::unique_ptr<ClRuntime> r = [] {
    std::string error;
    auto device = select_device(list_devices(), "", &error);
    if (!device) throw std::runtime_error(error);
    return std::make_unique<ClRuntime>(*device);
  }();
  return *r;
}

const char* const kScenes[] = {"mandelbulb", "menger", "sierpinski", "julia", "benchmark"};

// 65536 points spread over the scene's bounding sphere (a fixed lattice: the same points every
// run), where the DE does its full work near the surface and its early-out far from it.
std::vector<std::array<float, 3>> points_in(double radius) {
  std::vector<std::array<float, 3>> points;
  const int n = 40;  // 40^3 = 64000, then padded to 65536 with the centre region
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        points.push_back({static_cast<float>(radius * (2.0 * i / (n - 1) - 1)),
                          static_cast<float>(radius * (2.0 * j / (n - 1) - 1)),
                          static_cast<float>(radius * (2.0 * k / (n - 1) - 1))});
  while (points.size() < 65536) {
    const double t = static_cast<double>(points.size() % 1536) / 1536.0;
    points.push_back({static_cast<float>(0.5 * radius * std::cos(7 * t)),
                      static_cast<float>(0.5 * radius * std::sin(5 * t)),
                      static_cast<float>(0.5 * radius * (2 * t - 1))});
  }
  return points;
}

void BM_SceneDe(benchmark::State& state) {
  const std::string id = kScenes[state.range(0)];
  const Precision precision = state.range(1) ? Precision::Double : Precision::Float;
  const LoadOutcome o =
      load_scene_plugin(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  if (!o.scene) throw std::runtime_error(o.message);
  const auto params = make_default_state(o.scene->info).params;
  const auto points = points_in(o.scene->info.bounding_radius);
  probe_de(runtime(), o.scene->info, params, points, 0, precision);  // builds the kernel
  for (auto _ : state)
    benchmark::DoNotOptimize(probe_de(runtime(), o.scene->info, params, points, 0, precision));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(points.size()));
  state.SetLabel(id + (state.range(1) ? " double" : " float"));
}
BENCHMARK(BM_SceneDe)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1}})
    ->UseRealTime()  // the work runs on the device's threads, not this one
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

}  // namespace
}  // namespace fr

BENCHMARK_MAIN();
