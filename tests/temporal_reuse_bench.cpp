// What carrying earlier frames' samples into a new camera costs (app/temporal_reuse.hpp): the
// compose step alone, at 1280x720, on a synthetic flight over exact geometry (a sphere resting on
// a chequered plane, under a sky), so that no renderer's time is in the figure. Each frame's
// lattice (its colours and depths) is traced in double while the timing is paused; the timed loop
// composes the frames of the flight in order, as the explorer does. Google Benchmark; run
// ./build/tests/temporal_reuse_bench. Figures: time per frame, and pixels per second.
#include "app/temporal_reuse.hpp"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace fr {
namespace {

constexpr int kWidth = 1280, kHeight = 720, kWarmUpCycles = 2;

fr_camera camera_at(glm::dvec3 eye, glm::dvec3 target) {
  fr_camera c{};
  c.struct_size = sizeof c;
  for (int k = 0; k < 3; ++k) {
    c.eye[k] = eye[k];
    c.target[k] = target[k];
  }
  c.up[1] = 1;
  c.fov_deg = 60;
  return c;
}

// The distance along a unit ray to a unit sphere at the origin or the plane y = -1 (+inf: sky),
// and the colour there: the sphere shaded by its normal, the plane chequered.
void trace(const glm::dvec3& eye, const glm::dvec3& d, float& depth, uint8_t rgba[4]) {
  double t = std::numeric_limits<double>::infinity();
  const double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1, disc = b * b - c;
  bool sphere = false;
  if (disc > 0 && -b - std::sqrt(disc) > 0) {
    t = -b - std::sqrt(disc);
    sphere = true;
  }
  if (d.y < 0) {
    const double tp = (-1 - eye.y) / d.y;
    if (tp > 0 && tp < t) {
      t = tp;
      sphere = false;
    }
  }
  depth = static_cast<float>(t);
  const glm::dvec3 p = eye + d * t;
  if (!std::isfinite(t)) {
    rgba[0] = 120, rgba[1] = 160, rgba[2] = 220;
  } else if (sphere) {
    rgba[0] = static_cast<uint8_t>(127 + 127 * p.x);
    rgba[1] = static_cast<uint8_t>(127 + 127 * p.y);
    rgba[2] = static_cast<uint8_t>(127 + 127 * p.z);
  } else {
    const bool odd =
        (static_cast<int>(std::floor(p.x * 4)) + static_cast<int>(std::floor(p.z * 4))) & 1;
    rgba[0] = rgba[1] = rgba[2] = odd ? 230 : 30;
  }
  rgba[3] = 255;
}

struct TracedFrame {
  CameraRays rays;
  LatticePhase phase;
  std::vector<uint8_t> rgba8;
  std::vector<float> depth;
};

// Frame `f` of an endless flight that circles the sphere while bobbing and turning, as the
// explorer's bench path does, and its lattice for that frame's phase.
void trace_frame(uint64_t f, int stride, TracedFrame& tf) {
  const double a = 0.01 * static_cast<double>(f), r = 3.5 + 0.8 * std::sin(0.7 * a);
  tf.rays =
      make_camera_rays(camera_at({r * std::sin(a), 0.2 + 0.3 * std::sin(1.3 * a), r * std::cos(a)},
                                 {0.4 * std::sin(2.1 * a), -0.2, 0}),
                       kWidth, kHeight);
  tf.phase = lattice_phase(stride, stride, f);
  const int lw = tf.phase.width_px(kWidth), lh = tf.phase.height_px(kHeight);
  tf.rgba8.resize(static_cast<size_t>(lw) * lh * 4);
  tf.depth.resize(static_cast<size_t>(lw) * lh);
  for (int j = 0; j < lh; ++j)
    for (int i = 0; i < lw; ++i) {
      const size_t k = static_cast<size_t>(j) * lw + i;
      trace(tf.rays.eye,
            camera_ray_dir(tf.rays, tf.phase.x0 + i * stride, tf.phase.y0 + j * stride),
            tf.depth[k], &tf.rgba8[4 * k]);
    }
}

// The frames are traced with the timing paused: only compose is timed.
void BM_Compose(benchmark::State& state) {
  const int stride = static_cast<int>(state.range(0));
  TemporalReuse reuse;
  TracedFrame tf;
  uint64_t f = 0;
  for (; f < 2 * kWarmUpCycles * stride * stride; ++f) {  // a history as in steady flight
    trace_frame(f, stride, tf);
    reuse.compose(tf.rays, tf.phase, tf.rgba8.data(), tf.depth.data());
  }
  for (auto _ : state) {
    state.PauseTiming();
    trace_frame(f++, stride, tf);
    state.ResumeTiming();
    benchmark::DoNotOptimize(reuse.compose(tf.rays, tf.phase, tf.rgba8.data(), tf.depth.data()));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kWidth * kHeight);
  state.counters["reused_share"] =
      static_cast<double>(reuse.counts().reused) / (static_cast<double>(kWidth) * kHeight);
}
BENCHMARK(BM_Compose)->Arg(2)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace fr

BENCHMARK_MAIN();
