// renderer.hpp — one frame of a scene on an OpenCL device: assemble and build (cached) the
// scene's kernel, upload the frame constants and parameters, run the render and post kernels,
// read back the image.
#pragma once

#include "plugin/scene_instance.hpp"
#include "render/cl_runtime.hpp"
#include "render/render_settings.hpp"

#include <cstdint>
#include <vector>

namespace fr {

struct FrameImage {
  int width_px = 0;
  int height_px = 0;
  int lanes = 0;               // lane width the frame was rendered with
  std::vector<uint8_t> rgba8;  // tonemapped, sRGB, 4 bytes per pixel, rows top to bottom
  // Filled only when asked for (render's read_linear):
  std::vector<float> linear_rgba;  // linear HDR, 4 floats per pixel
  std::vector<float> depth;        // distance along the ray to the hit; +inf for a miss
  std::vector<float> steps;        // DE evaluations of the primary ray
};

class Renderer {
 public:
  explicit Renderer(ClRuntime& runtime);

  // Renders `state` of `info`. Throws KernelBuildError if the scene's kernel does not compile,
  // ClError if the device fails. `read_linear` also reads back the float buffers.
  FrameImage render(const SceneInfo& info, const SceneState& state, const RenderSettings& settings,
                    bool read_linear = false);

  // The lane width a frame with these settings uses on this device.
  int lanes_for(const RenderSettings& settings) const;

 private:
  void ensure_buffers(size_t pixel_count);

  ClRuntime& runtime_;
  size_t buffer_pixels_ = 0;
  ClBufferHandle constants_, params_, hdr_, depth_, steps_, rgba8_;
  size_t params_bytes_ = 0;
};

}  // namespace fr
