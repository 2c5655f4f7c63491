// sweep_reference.hpp — the converged picture a sweep measures against, computed by the
// renderer itself at settings no configuration uses: double precision end to end, plain sphere
// tracing (no over-relaxation), a budget of 5000 steps, 16 samples per pixel (1024 when the
// base integrator is path), and a hit threshold divided by 4 until the picture stops changing
// (path-traced: until the surface stops moving; its picture's noise keeps changing) or 4
// refinements. How much the last
// refinement still changed is reported: no configuration can be measured as better than that.
#pragma once

#include "render/renderer.hpp"
#include "scene/scene_data.hpp"
#include "sweep/sweep_metrics.hpp"
#include "worker/render_worker.hpp"

#include <filesystem>
#include <functional>
#include <string>

namespace fr {

struct SweepReference {
  ReferenceImage image;
  double hit_threshold_k = 0;       // of the last refinement
  int refinements = 0;              // renders it took (1 + refinements of the threshold)
  double convergence_mae = 0;       // mean |difference| of the last two refinements, 8-bit units
  double convergence_depth_px = 0;  // median depth difference of the last two, in footprints
  bool from_cache = false;
  int samples = 0;  // per pixel of its picture
};

// Samples per pixel of the reference picture; path-traced, many more (its noise is what the
// path tracer's error converges to: at 1024 samples a 32nd of one sample's).
constexpr int kReferenceSamples = 16;
constexpr int kPathReferenceSamples = 1024;

// The settings a reference is rendered with, from the sweep's base settings: double precision,
// plain sphere tracing from every ray's own origin, generous step budgets, central differences,
// no refinement steps, fast math or denoising, never a step scale above 1 (the hit threshold then
// shrinks from the base's, refinement by refinement).
// path_samples: a path-traced reference's samples (sweep --reference-samples).
RenderSettings reference_settings(const RenderSettings& base,
                                  int path_samples = kPathReferenceSamples);

// A key for the cache: the scene (id, version), its parameter values, camera, lights, time,
// every field of reference_settings(settings) (render_settings.hpp's visit_render_fields, so a
// new field cannot stay out), the device, and the assembled kernel source (so a changed
// renderer or DE never reuses an old reference).
std::string reference_key(const SceneInfo& info, const SceneState& state,
                          const RenderSettings& settings, const std::string& device_name,
                          int path_samples = kPathReferenceSamples);

// The reference for this view, from `cache_dir` (file <key>.ref) when there, else computed
// (progress(k, refinement) is called before each refinement; returning false abandons the
// reference: nothing is cached and the result is empty) and stored there atomically. A cache
// file that cannot be read is recomputed; one that cannot be written is reported on *warning.
SweepReference make_reference(RenderWorker& renderer, const SceneInfo& info,
                              const SceneState& state, const RenderSettings& settings,
                              const std::string& device_name,
                              const std::filesystem::path& cache_dir,
                              const std::function<bool(double, int)>& progress,
                              std::string* warning, int path_samples = kPathReferenceSamples);

}  // namespace fr
