#include "render/renderer.hpp"

#include "render/camera.hpp"
#include "render/frame_constants.hpp"
#include "render/kernel_assembly.hpp"
#include "render/kernel_sources.hpp"

#include <stdexcept>

namespace fr {
namespace {

ClBufferHandle make_buffer(cl_context ctx, cl_mem_flags flags, size_t bytes, const char* what) {
  cl_int err = CL_SUCCESS;
  ClBufferHandle b(clCreateBuffer(ctx, flags, bytes, nullptr, &err));
  cl_check(err, "clCreateBuffer", std::string("allocating ") + what);
  return b;
}

template <typename T>
void set_arg(cl_kernel k, cl_uint index, const T& value) {
  cl_check(clSetKernelArg(k, index, sizeof(T), &value), "clSetKernelArg");
}

size_t round_up_div(size_t n, size_t d) {
  return (n + d - 1) / d;
}

}  // namespace

Renderer::Renderer(ClRuntime& runtime) : runtime_(runtime) {
  constants_ = make_buffer(runtime_.context(), CL_MEM_READ_ONLY, sizeof(fr_frame_constants),
                           "frame constants");
}

int Renderer::lanes_for(const RenderSettings& s) const {
  return s.lanes > 0 ? s.lanes : preferred_lanes(runtime_.device());
}

void Renderer::ensure_buffers(size_t n) {
  if (n == buffer_pixels_) return;
  cl_context ctx = runtime_.context();
  const size_t padded = round_up_div(n, 4) * 4;  // the post kernel works on whole quads
  hdr_ = make_buffer(ctx, CL_MEM_READ_WRITE, padded * 4 * sizeof(float), "the HDR image");
  depth_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n * sizeof(float), "the depth buffer");
  steps_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n * sizeof(float), "the step buffer");
  rgba8_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, padded * 4, "the display image");
  buffer_pixels_ = n;
}

FrameImage Renderer::render(const SceneInfo& info, const SceneState& state,
                            const RenderSettings& settings, bool read_linear) {
  if (settings.precision == Precision::Double && !runtime_.device().has_fp64)
    throw std::runtime_error("device " + runtime_.device().name + " has no double precision");
  const int lanes = lanes_for(settings);
  KernelConfig config{lanes, settings.precision, enabled_stages(info, settings.disabled_stages)};
  const AssembledKernel assembled = assemble_render_kernel(info, state.params, config);
  cl_program program =
      runtime_.program(assembled.source, assembled.build_options, assembled.description);
  cl_kernel render_kernel = runtime_.kernel(program, "fr_render");

  // The post stage does not depend on the scene: one program for all.
  static const std::string post_source = std::string(kernel_source("post.cl"));
  cl_kernel post_kernel =
      runtime_.kernel(runtime_.program(post_source, "-cl-std=CL1.2", "post-processing"), "fr_post");

  const int w = settings.width_px, h = settings.height_px;
  const size_t n = static_cast<size_t>(w) * h;
  ensure_buffers(n);
  cl_command_queue q = runtime_.queue();

  const CameraRays rays = make_camera_rays(state.camera, w, h);
  const fr_frame_constants fc = make_frame_constants(rays, state, settings);
  cl_check(
      clEnqueueWriteBuffer(q, constants_.get(), CL_FALSE, 0, sizeof fc, &fc, 0, nullptr, nullptr),
      "clEnqueueWriteBuffer", "uploading frame constants");
  const std::vector<uint8_t> params = pack_scene_params(info, state.params);
  if (params.size() != params_bytes_) {
    params_ = make_buffer(runtime_.context(), CL_MEM_READ_ONLY, params.size(), "scene parameters");
    params_bytes_ = params.size();
  }
  cl_check(clEnqueueWriteBuffer(q, params_.get(), CL_FALSE, 0, params.size(), params.data(), 0,
                                nullptr, nullptr),
           "clEnqueueWriteBuffer", "uploading scene parameters");

  cl_mem c = constants_.get(), p = params_.get(), hdr = hdr_.get(), d = depth_.get(),
         s = steps_.get(), out8 = rgba8_.get();
  set_arg(render_kernel, 0, c);
  set_arg(render_kernel, 1, p);
  set_arg(render_kernel, 2, hdr);
  set_arg(render_kernel, 3, d);
  set_arg(render_kernel, 4, s);
  const TileShape tile = tile_shape(lanes);
  const size_t global[2] = {round_up_div(w, tile.width_px), round_up_div(h, tile.height_px)};
  cl_check(
      clEnqueueNDRangeKernel(q, render_kernel, 2, nullptr, global, nullptr, 0, nullptr, nullptr),
      "clEnqueueNDRangeKernel", "rendering " + assembled.description);

  const cl_int quad_count = static_cast<cl_int>(round_up_div(n, 4));
  const cl_float exposure = settings.exposure;
  set_arg(post_kernel, 0, hdr);
  set_arg(post_kernel, 1, out8);
  set_arg(post_kernel, 2, exposure);
  set_arg(post_kernel, 3, quad_count);
  const size_t post_global = round_up_div(n, 4);  // four pixels per work-item
  cl_check(clEnqueueNDRangeKernel(q, post_kernel, 1, nullptr, &post_global, nullptr, 0, nullptr,
                                  nullptr),
           "clEnqueueNDRangeKernel", "post-processing");

  FrameImage img;
  img.width_px = w;
  img.height_px = h;
  img.lanes = lanes;
  img.rgba8.resize(n * 4);
  cl_check(clEnqueueReadBuffer(q, out8, CL_TRUE, 0, n * 4, img.rgba8.data(), 0, nullptr, nullptr),
           "clEnqueueReadBuffer", "reading the image");
  if (read_linear) {
    img.linear_rgba.resize(n * 4);
    img.depth.resize(n);
    img.steps.resize(n);
    cl_check(clEnqueueReadBuffer(q, hdr, CL_FALSE, 0, n * 16, img.linear_rgba.data(), 0, nullptr,
                                 nullptr),
             "clEnqueueReadBuffer");
    cl_check(clEnqueueReadBuffer(q, d, CL_FALSE, 0, n * 4, img.depth.data(), 0, nullptr, nullptr),
             "clEnqueueReadBuffer");
    cl_check(clEnqueueReadBuffer(q, s, CL_TRUE, 0, n * 4, img.steps.data(), 0, nullptr, nullptr),
             "clEnqueueReadBuffer");
  }
  return img;
}

}  // namespace fr
