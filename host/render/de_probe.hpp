// de_probe.hpp — the scene's distance estimate at arbitrary points, computed on the device by
// the scene's own OpenCL DE (kernels/probe.cl). There is no C++ copy of any DE.
#pragma once

#include "render/cl_runtime.hpp"
#include "render/kernel_assembly.hpp"  // PairOrigin
#include "render/render_settings.hpp"
#include "scene/scene_data.hpp"

#include "frame_constants.h"

#include <array>
#include <vector>

namespace fr {

// DE values at `points` (world space) with parameter values `params`. lanes 0 picks the
// device's width. Throws KernelBuildError or ClError like the renderer. In double-double the
// points are relative to `origin` (the world's origin when null; kernels/dd_relative.cl), and
// the estimate runs every iteration in pairs.
std::vector<float> probe_de(ClRuntime& runtime, const SceneInfo& info,
                            const std::vector<fr_value>& params,
                            const std::vector<std::array<float, 3>>& points, int lanes = 0,
                            Precision precision = Precision::Float,
                            const PairOrigin* origin = nullptr);

// What a material function (scene_material) returns at `points`, before the renderer clamps it:
// kMaterialFloats floats a point, in material_t's order (kernels/prelude.cl, material_probe.cl),
// its input the default material that the frame constants `fc` give (render settings' values).
constexpr size_t kMaterialFloats = 19;
std::vector<float> probe_material(ClRuntime& runtime, const SceneInfo& info,
                                  const std::vector<fr_value>& params, const fr_frame_constants& fc,
                                  const std::vector<std::array<float, 3>>& points);

// The surface function's albedo (scene_surface) at `points`: 3 floats a point.
std::vector<float> probe_albedo(ClRuntime& runtime, const SceneInfo& info,
                                const std::vector<fr_value>& params,
                                const std::vector<std::array<float, 3>>& points,
                                Precision precision = Precision::Float);

}  // namespace fr
