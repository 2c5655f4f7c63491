// kernel_assembly.hpp — pasting one scene's kernels together.
//
// For each (scene, stages, modes, precision, lane width) the host builds: generated defines, the
// shared frame-constants struct, the lane-generic prelude, a parameter struct generated from the
// scene's table (specialised parameters baked in as constants), the scene's DE (with the helper
// library files it #includes) and surface source, and the renderer stages — only those the
// scene needs and the user left on. Each piece starts with a #line directive naming its file, so
// compiler messages point into the scene's own source.
#pragma once

#include "io/dd_text.hpp"  // DoubleDouble
#include "render/render_settings.hpp"
#include "scene/scene_data.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace fr {

// Host-only stage bit beside the ABI's FR_FEATURE_* bits: depth of field is the user's choice,
// not a scene's need.
constexpr fr_features kStageDepthOfField = 1ull << 32;
// Host-only and not an effect: the cone pre-pass (kernels/cone.cl), a faster way to the same
// primary hits. On unless the user switched it off (render.cone_prepass) or the lens is on.
constexpr fr_features kStageCone = 1ull << 33;
// Host-only: the sky is an HDR panorama (render.environment; kernels/environment.cl), not the
// gradient.
constexpr fr_features kStageEnvironment = 1ull << 34;

struct KernelConfig {
  int lanes = 16;
  Precision precision = Precision::Float;
  // FR_FEATURE_*, kStageDepthOfField, kStageCone and kStageEnvironment compiled in
  fr_features stages = 0;
  Integrator integrator = RenderSettings{}.integrator;  // render.cl or path.cl
  // The modes, by default the settings' defaults (RenderSettings is their one home).
  ShadingModel shading = RenderSettings{}.shading;
  NormalMethod normals = RenderSettings{}.normals;
  AoMethod ao_method = RenderSettings{}.ao_method;
  ShadowMethod shadow_method = RenderSettings{}.shadow_method;
  FogMethod fog_method = RenderSettings{}.fog_method;
  bool fast_math = RenderSettings{}.fast_math;      // -cl-fast-relaxed-math (kernel_assembly.cpp)
  bool quick_build = RenderSettings{}.quick_build;  // -cl-opt-disable (render_settings.hpp)
  // FR_COUNT_EVALS: per-stage DE counters (eval_counts.cl)
  bool count_evaluations = RenderSettings{}.count_evaluations;
  // FR_RELAX_ADAPTIVE: march.cl's omega follows the DE's slope
  bool adaptive_relaxation = RenderSettings{}.adaptive_relaxation;
  Readback outputs = RenderSettings{}.outputs;  // FR_OUTPUTS: the passes render.cl writes
};

// The kernel configuration a frame with these settings compiles for this scene.
KernelConfig make_kernel_config(const SceneInfo& info, const RenderSettings& settings, int lanes);

struct AssembledKernel {
  std::string source;
  std::string build_options;
  std::string description;  // "scene 'mandelbulb' render kernel (lanes 16, float, stages: ao)"
};

// Pixels one work-item renders at a lane width: 1x1, 2x2, 4x2 or 4x4 (as FR_TILE_W/H in
// kernels/prelude.cl).
struct TileShape {
  int width_px;
  int height_px;
};
TileShape tile_shape(int lanes);

// Stages that a frame of `info` compiles: what it needs and the user did not switch off.
fr_features enabled_stages(const SceneInfo& info, fr_features disabled_by_user);

// Names of the stages in `stages`, comma-separated ("ao, shadows"), or "none".
// Every optional stage (FR_FEATURE_* the renderer implements, and kStageDepthOfField).
fr_features all_optional_stages();

std::string stage_names(fr_features stages);

// Both throw KernelBuildError when a scene source #includes a library file that does not exist.
AssembledKernel assemble_render_kernel(const SceneInfo& info, const std::vector<fr_value>& values,
                                       const KernelConfig& config);
// The scene's DE alone, as kernel fr_probe_de (kernels/probe.cl); stages and modes are ignored.
AssembledKernel assemble_probe_kernel(const SceneInfo& info, const std::vector<fr_value>& values,
                                      const KernelConfig& config);

// The scene's material function (scene_material) with its surface source, as kernel
// fr_probe_material (kernels/material_probe.cl); only for a scene whose surface source defines it.
AssembledKernel assemble_material_probe_kernel(const SceneInfo& info,
                                               const std::vector<fr_value>& values,
                                               const KernelConfig& config);
// Whether the scene's surface source defines a material function (path tracing's materials).
bool has_material_function(const SceneInfo& info);

// Whether the scene's DE source defines a pair estimate, which double-double kernels need:
//   real_t scene_de_dd(dd3_t p, __constant const scene_params_t* params, real_t resolution)
// (fr/dd.cl's types; `resolution` is the distance the estimate must resolve at p, so that it
// may finish in double once its roundings cost less; docs/deep_zoom.md).
bool has_pair_estimate(const SceneInfo& info);

// Where a double-double kernel's coordinates start (kernels/dd_relative.cl): its stages work in
// double relative to `eye`, and the scene's estimate gets eye + p as pairs, to be resolved to
// resolution_rad times the distance from the eye (a pixel's footprint there, or the hit
// threshold's when finer).
struct PairOrigin {
  DoubleDouble eye[3];
  float resolution_rad = 0;
};

// The kernel-side parameter block: runtime (non-specialised) parameters in table order, each
// float/int/bool as 4 bytes and each vec3/color as float[3]; at least 4 bytes. A double-double
// kernel's block ends with its origin, which must then be given.
std::vector<uint8_t> pack_scene_params(const SceneInfo& info, const std::vector<fr_value>& values,
                                       const PairOrigin* origin = nullptr);

}  // namespace fr
