#include "render/renderer.hpp"

#include "render/environment_map.hpp"

#include "render/camera.hpp"
#include "render/dd_selftest.hpp"
#include "render/eye_relative.hpp"
#include "render/frame_constants.hpp"
#include "render/kernel_assembly.hpp"
#include "render/kernel_sources.hpp"
#include "render/precision.hpp"

extern "C" {
#include "frame_constants.h"
}

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
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

// The whole image's camera (a window's pixels are its pixels: frame_constants.h).
CameraRays whole_image_rays(const fr_camera& camera, const RenderSettings& s) {
  const ImageWindow& win = s.window;
  if (win.full_width_px <= 0)
    return make_camera_rays(camera, s.width_px, s.height_px, s.mirror_vertical, s.pixel_corners);
  return make_camera_rays(camera, win.full_width_px, win.full_height_px, s.mirror_vertical,
                          s.pixel_corners);
}

size_t round_up_div(size_t n, size_t d) {
  return (n + d - 1) / d;
}

constexpr size_t kCountWords = size_t{FR_COUNT_SLOTS} * FR_COUNT_CELLS * 2;
constexpr size_t kCountBytes = kCountWords * sizeof(cl_uint);

}  // namespace

Renderer::Renderer(ClRuntime& runtime) : runtime_(runtime) {
  constants_ = make_buffer(runtime_.context(), CL_MEM_READ_ONLY, sizeof(fr_frame_constants),
                           "frame constants");
  counts_ = make_buffer(runtime_.context(), CL_MEM_READ_WRITE, kCountBytes, "the DE counters");
}

namespace {
std::pair<std::string, size_t> scene_code_key(const SceneInfo& info) {
  const std::hash<std::string> hash;
  return {info.id, hash(info.de_source) ^ (hash(info.surface_source) * 0x9e3779b97f4a7c15ull)};
}
}  // namespace

int Renderer::lanes_for(const SceneInfo& info, const RenderSettings& s) const {
  const int lanes = resolve_lanes(s.lanes, &runtime_.device(), s.precision);
  if (s.lanes == 0 && lanes > kPacketLanes && narrow_scenes_.count(scene_code_key(info)))
    return kPacketLanes;
  return lanes;
}

void Renderer::ensure_buffers(size_t n) {
  frame_pixels_ = n;
  // Grow only: the explorer changes the resolution scale every frame, and reallocating (and
  // faulting in) the buffers each time cost up to 100 ms a frame on PoCL.
  if (n <= buffer_pixels_) return;
  cl_context ctx = runtime_.context();
  const size_t padded = round_up_div(n, 4) * 4;  // the post kernel works on whole quads
  hdr_ = make_buffer(ctx, CL_MEM_READ_WRITE, padded * 4 * sizeof(float), "the HDR image");
  depth_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n * sizeof(float), "the depth buffer");
  steps_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n * sizeof(float), "the step buffer");
  factors_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n * 2 * sizeof(float), "the AO and shadow buffer");
  status_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n, "the ray status buffer");
  normal_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n * 3 * sizeof(float), "the normal buffer");
  albedo_ = make_buffer(ctx, CL_MEM_WRITE_ONLY, n * 3 * sizeof(float), "the albedo buffer");
  for (auto& b : denoised_) b.reset();  // made when first needed
  buffer_pixels_ = n;
}

FrameImage Renderer::render(const SceneInfo& info, const SceneState& state,
                            const RenderSettings& settings, bool read_linear) {
  return render_all_samples(*this, info, state, settings, read_linear);
}

void Renderer::render_sample(const SceneInfo& info, const SceneState& state,
                             const RenderSettings& requested, int sample_index, Readback outputs,
                             RowBand rows) {
  if ((requested.precision == Precision::Double ||
       requested.precision == Precision::DoubleDouble) &&
      !runtime_.device().has_fp64)
    throw std::runtime_error("device " + runtime_.device().name + " has no double precision" +
                             (requested.precision == Precision::DoubleDouble
                                  ? ", which double-double (render.precision dd) is made of"
                                  : ""));
  const int w = requested.width_px, h = requested.height_px;
  if (rows.rows_px == 0) rows = RowBand{0, h};
  const int end_row = rows.first_row_px + rows.rows_px;
  if (rows.first_row_px < 0 || rows.rows_px < 0 || end_row > h ||
      rows.first_row_px % kRowBandAlign != 0 || (end_row != h && rows.rows_px % kRowBandAlign != 0))
    throw std::invalid_argument("rows " + std::to_string(rows.first_row_px) + " to " +
                                std::to_string(end_row) + " are not a band of a " +
                                std::to_string(w) + "x" + std::to_string(h) + " image's rows");
  // Auto is decided once per accumulation, at its first sample.
  RenderSettings settings = requested;
  settings.precision = sample_index == 0 || requested.precision != Precision::Auto
                           ? choose_precision(info, state, requested)
                           : last_precision_;
  last_precision_ = settings.precision;
  const bool pairs = settings.precision == Precision::DoubleDouble;
  if (pairs) {
    check_pair_frame(info, settings);
    // Pairs only where the device keeps their error terms, checked once.
    if (!pairs_refused_) {
      const DdSelftest test = dd_selftest(runtime_);
      pairs_refused_ = test.exact ? "" : test.failed;
    }
    if (!pairs_refused_->empty())
      throw std::runtime_error("render.precision dd: device " + runtime_.device().name +
                               " does not keep double-double's error terms (" + *pairs_refused_ +
                               ")");
  } else if (check_camera(state.camera) && !check_camera(state.camera, state.camera_lo))
    throw std::invalid_argument(
        "camera: the eye and target lie closer than double tells apart; only render.precision "
        "dd renders such a view" +
        std::string(has_pair_estimate(info)
                        ? ""
                        : ", and scene '" + info.id + "' has no pair estimate (scene_de_dd)"));
  int lanes = lanes_for(info, settings);
  std::string description;
  // The denoiser is guided by the passes.
  if (settings.denoise) outputs = Readback::Everything;
  settings.outputs = outputs;
  last_outputs_ = outputs;
  const cl_program program = render_program(info, state, settings, &lanes, &description);
  cl_kernel kernel = runtime_.kernel(program, "fr_render");
  const bool cone = make_kernel_config(info, settings, lanes).stages & kStageCone;

  const size_t n = static_cast<size_t>(w) * h;
  ensure_buffers(n);
  last_lanes_ = lanes;
  cl_command_queue q = runtime_.queue();

  cl_mem environment = nullptr;
  const fr_frame_constants fc = upload_frame(info, state, settings, sample_index, &environment);

  if (sample_index == 0) counted_samples_ = 0;
  denoise_pass_ = denoise_next_row_ = 0;  // a new mean: nothing of it is filtered
  if (settings.count_evaluations) {
    if (counted_samples_ == 0) {
      const cl_uint zero = 0;
      cl_check(clEnqueueFillBuffer(q, counts_.get(), &zero, sizeof zero, 0, kCountBytes, 0, nullptr,
                                   nullptr),
               "clEnqueueFillBuffer", "clearing the DE counters");
    }
    ++counted_samples_;
  }
  const TileShape tile = tile_shape(lanes);
  // On CPU devices, one work-item per work-group: PoCL otherwise picks groups of thousands of
  // work-items and keeps all their private packets (a few KB each) on one thread's stack, which
  // overflowed at 640x360. The packets are the parallelism; groups add nothing here.
  const size_t one[2] = {1, 1};
  const size_t* local = (runtime_.device().type & CL_DEVICE_TYPE_CPU) ? one : nullptr;
  if (cone) enqueue_cone(program, fc, lanes, rows, description);
  const cl_mem args[] = {constants_.get(), params_.get(),  hdr_.get(),    depth_.get(),
                         steps_.get(),     factors_.get(), status_.get(), normal_.get(),
                         albedo_.get(),    counts_.get(),  cone_t_.get(), cone_ao_.get(),
                         environment};
  for (cl_uint i = 0; i < std::size(args); ++i) set_arg(kernel, i, args[i]);
  // A band: the work-items of its rows, numbered as in the whole image's launch.
  const size_t offset[2] = {0, static_cast<size_t>(rows.first_row_px / tile.height_px)};
  const size_t global[2] = {round_up_div(w, tile.width_px),
                            round_up_div(rows.rows_px, tile.height_px)};
  cl_check(clEnqueueNDRangeKernel(q, kernel, 2, offset, global, local, 0, nullptr, nullptr),
           "clEnqueueNDRangeKernel", "rendering " + description);
}

fr_frame_constants Renderer::upload_frame(const SceneInfo& info, const SceneState& state,
                                          const RenderSettings& settings, int sample_index,
                                          cl_mem* environment) {
  cl_command_queue q = runtime_.queue();
  // Double-double: the scene seen from its eye (render/eye_relative.hpp).
  const std::optional<EyeRelativeView> relative = settings.precision == Precision::DoubleDouble
                                                      ? std::optional(eye_relative_view(state, 0))
                                                      : std::nullopt;
  const SceneState& drawn = relative ? relative->state : state;
  const CameraRays rays = whole_image_rays(drawn.camera, settings);
  fr_frame_constants fc = make_frame_constants(
      rays, drawn, settings, sample_index, relative ? relative->bounding_centre : glm::dvec3(0));
  *environment = environment_memory(settings);
  fc.env_width = environment_width_px_;
  fc.env_height = environment_height_px_;
  last_pixel_angle_rad_ = fc.pixel_angle_rad;
  cl_check(
      clEnqueueWriteBuffer(q, constants_.get(), CL_FALSE, 0, sizeof fc, &fc, 0, nullptr, nullptr),
      "clEnqueueWriteBuffer", "uploading frame constants");
  std::optional<PairOrigin> origin;
  if (relative) {
    origin = relative->origin;
    origin->resolution_rad =
        static_cast<float>(rays.pixel_angle_rad * std::min(1.0, double(settings.hit_threshold_k)));
  }
  const std::vector<uint8_t> params =
      pack_scene_params(info, state.params, origin ? &*origin : nullptr);
  if (params.size() != params_bytes_) {
    params_ = make_buffer(runtime_.context(), CL_MEM_READ_ONLY, params.size(), "scene parameters");
    params_bytes_ = params.size();
  }
  // Blocking: `params` is a local (and `fc`, once returned).
  cl_check(clEnqueueWriteBuffer(q, params_.get(), CL_TRUE, 0, params.size(), params.data(), 0,
                                nullptr, nullptr),
           "clEnqueueWriteBuffer", "uploading scene parameters");
  return fc;
}

void Renderer::enqueue_cone(cl_program program, const fr_frame_constants& fc, int lanes,
                            RowBand rows, const std::string& description) {
  const size_t blocks = static_cast<size_t>(fc.cone_blocks_x) * fc.cone_blocks_y;
  if (blocks > cone_blocks_) {
    cone_t_ = make_buffer(runtime_.context(), CL_MEM_READ_WRITE, blocks * sizeof(float),
                          "the cone pre-pass's starts");
    cone_ao_ = make_buffer(runtime_.context(), CL_MEM_READ_WRITE, blocks * sizeof(float),
                           "the cone pre-pass's AO steps");
    cone_blocks_ = blocks;
  }
  const TileShape tile = tile_shape(lanes);
  const size_t one[2] = {1, 1};  // as render_sample's work-groups
  const size_t* local = (runtime_.device().type & CL_DEVICE_TYPE_CPU) ? one : nullptr;
  cl_kernel cone_kernel = runtime_.kernel(program, "fr_cone");
  const cl_mem cone_args[] = {constants_.get(), params_.get(), cone_t_.get(), cone_ao_.get(),
                              counts_.get()};
  for (cl_uint i = 0; i < std::size(cone_args); ++i) set_arg(cone_kernel, i, cone_args[i]);
  // The work-items whose blocks hold the band's rows (pixel row y is in block row
  // (y + phase) / FR_CONE_BLOCK; bands that share a block row both compute it, alike).
  const int end_row = rows.first_row_px + rows.rows_px;
  const size_t first_block = (rows.first_row_px + fc.cone_phase_y) / FR_CONE_BLOCK;
  const size_t last_block = (end_row - 1 + fc.cone_phase_y) / FR_CONE_BLOCK;
  const size_t cone_offset[2] = {0, first_block / tile.height_px};
  const size_t cone_global[2] = {round_up_div(fc.cone_blocks_x, tile.width_px),
                                 last_block / tile.height_px + 1 - cone_offset[1]};
  cl_check(clEnqueueNDRangeKernel(runtime_.queue(), cone_kernel, 2, cone_offset, cone_global, local,
                                  0, nullptr, nullptr),
           "clEnqueueNDRangeKernel", "the cone pre-pass of " + description);
}

double Renderer::cone_hit_bound(const SceneInfo& info, const SceneState& state,
                                const RenderSettings& settings) {
  int lanes = lanes_for(info, settings);
  if (!(make_kernel_config(info, settings, lanes).stages & kStageCone)) return 0;
  std::string description;
  const cl_program program = render_program(info, state, settings, &lanes, &description);
  cl_mem environment = nullptr;
  const fr_frame_constants fc = upload_frame(info, state, settings, 0, &environment);
  enqueue_cone(program, fc, lanes, RowBand{0, settings.height_px}, description);
  std::vector<float> starts(static_cast<size_t>(fc.cone_blocks_x) * fc.cone_blocks_y);
  cl_check(clEnqueueReadBuffer(runtime_.queue(), cone_t_.get(), CL_TRUE, 0,
                               starts.size() * sizeof(float), starts.data(), 0, nullptr, nullptr),
           "clEnqueueReadBuffer", "reading the cone pre-pass's starts");
  // A block's rays hit nothing nearer than its start; a negative start: they hit nothing at all
  // (cone.cl). A start that is not a number bounds nothing.
  double bound = INFINITY;
  for (const float t : starts) {
    if (std::isnan(t)) return 0;
    if (t >= 0) bound = std::min(bound, double(t));
  }
  return bound;
}

Precision Renderer::choose_precision(const SceneInfo& info, const SceneState& state,
                                     const RenderSettings& requested) {
  const Precision chosen = resolve_precision(runtime_, info, state, requested);
  if (requested.precision != Precision::Auto || chosen != Precision::Double) return chosen;
  // The eye is near some surface, yet the primary hits may all lie far off (a close-up that
  // looks past a nearby part of the fractal): the cone pre-pass, in double, bounds every block's
  // nearest hit from below, and float resolves the view when it resolves the nearest bound.
  // (The pass costs under 1% of a frame's evaluations.)
  RenderSettings in_double = requested;
  in_double.precision = Precision::Double;
  const CameraRays rays = view_camera_rays(state, requested.width_px, requested.height_px,
                                           requested.mirror_vertical, requested.pixel_corners);
  return float_resolves_beyond(cone_hit_bound(info, state, in_double), rays, state.bounding_radius)
             ? Precision::Float
             : Precision::Double;
}

cl_mem Renderer::environment_memory(const RenderSettings& settings) {
  const std::string path(settings.environment.view());
  if (path.empty()) {
    // The kernel takes the argument either way; without a panorama it reads nothing.
    if (!no_environment_)
      no_environment_ = make_buffer(runtime_.context(), CL_MEM_READ_ONLY, sizeof(float),
                                    "the absent environment image");
    environment_width_px_ = environment_height_px_ = 0;
    return no_environment_.get();
  }
  // The file's identity: its path, size and time of change (an edited panorama is read again).
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  const auto changed = std::filesystem::last_write_time(path, ec);
  const std::string identity =
      path + '\n' + std::to_string(ec ? 0 : size) + '\n' +
      std::to_string(ec ? 0 : static_cast<long long>(changed.time_since_epoch().count()));
  if (identity != environment_path_) {
    environment_.reset();
    environment_path_.clear();
    EnvironmentImage image;
    std::string error;
    // The settings checked the file when they were read; it may have changed since.
    if (!read_environment_image(path, &image, &error))
      throw std::runtime_error("render.environment: " + error);
    const std::vector<float> buffer = environment_buffer(image);
    const size_t bytes = buffer.size() * sizeof(float);
    environment_ =
        make_buffer(runtime_.context(), CL_MEM_READ_ONLY, bytes, "the environment image");
    cl_check(clEnqueueWriteBuffer(runtime_.queue(), environment_.get(), CL_TRUE, 0, bytes,
                                  buffer.data(), 0, nullptr, nullptr),
             "clEnqueueWriteBuffer", "uploading the environment image");
    environment_path_ = identity;
    environment_width_px_ = image.width_px;
    environment_height_px_ = image.height_px;
  }
  return environment_.get();
}

cl_program Renderer::render_program(const SceneInfo& info, const SceneState& state,
                                    const RenderSettings& settings, int* lanes,
                                    std::string* description) {
  const auto build = [&] {
    const AssembledKernel assembled =
        assemble_render_kernel(info, state.params, make_kernel_config(info, settings, *lanes));
    *description = assembled.description;
    return runtime_.program(assembled.source, assembled.build_options, assembled.description);
  };
  if (settings.lanes != 0 || *lanes <= kPacketLanes) return build();
  try {
    return build();
  } catch (const KernelBuildError& e) {
    // The scene's code calls what wide_lanes.cl does not overload: render as 16-lane packets.
    spdlog::warn("scene '{}' does not build at {} lanes ({}); it renders at {} lanes, slower",
                 info.id, *lanes, first_build_error(e.what()), kPacketLanes);
    narrow_scenes_.insert(scene_code_key(info));
    *lanes = kPacketLanes;
    return build();
  }
}

Precision Renderer::prepare(const SceneInfo& info, const SceneState& state,
                            const RenderSettings& requested) {
  RenderSettings settings = requested;
  settings.precision = choose_precision(info, state, requested);
  if (settings.precision == Precision::DoubleDouble) check_pair_frame(info, settings);
  std::string description;
  int lanes = lanes_for(info, settings);
  render_program(info, state, settings, &lanes, &description);
  post_kernel();
  return settings.precision;
}

cl_kernel Renderer::post_kernel() {
  // The post stage does not depend on the scene: one program for all.
  static const std::string post_source = std::string(kernel_source("post.cl"));
  return runtime_.kernel(runtime_.program(post_source, "-cl-std=CL1.2", "post-processing"),
                         "fr_post");
}

FramePassPointers size_frame_image(FrameImage& img, int width_px, int height_px, Readback what) {
  const size_t n = static_cast<size_t>(width_px) * height_px;
  img.width_px = width_px;
  img.height_px = height_px;
  const bool steps = what != Readback::Display, all = what == Readback::Everything;
  img.rgba8.resize(n * 4);
  img.steps.resize(steps ? n : 0);
  img.ray_status.resize(steps ? n : 0);
  img.linear_rgba.resize(all ? n * 4 : 0);
  img.depth.resize(all ? n : 0);
  img.occlusion.resize(all ? n : 0);
  img.shadow.resize(all ? n : 0);
  img.normal.resize(all ? n * 3 : 0);
  img.albedo.resize(all ? n * 3 : 0);
  FramePassPointers p;
  p.rgba8 = img.rgba8.data();
  if (steps) {
    p.steps = img.steps.data();
    p.ray_status = img.ray_status.data();
  }
  if (all) {
    p.linear_rgba = img.linear_rgba.data();
    p.depth = img.depth.data();
    p.occlusion = img.occlusion.data();
    p.shadow = img.shadow.data();
    p.normal = img.normal.data();
    p.albedo = img.albedo.data();
  }
  return p;
}

void Renderer::finish(const RenderSettings& settings, Readback what, FrameImage& img) {
  const FinishedFrame f = finish_into(
      settings, what, size_frame_image(img, settings.width_px, settings.height_px, what));
  img.lanes = f.lanes;
  img.precision = f.precision;
}

void Renderer::set_display_memory(uint8_t* memory, size_t bytes) {
  display_memory_ = memory;
  display_bytes_ = bytes;
}

Renderer::FinishedFrame Renderer::finish_into(const RenderSettings& settings, Readback what,
                                              const FramePassPointers& out) {
  if (static_cast<int>(what) > static_cast<int>(last_outputs_))
    throw std::logic_error("Renderer::finish: reading back passes the samples did not write");
  if (static_cast<size_t>(settings.width_px) * settings.height_px != frame_pixels_)
    throw std::logic_error("Renderer::finish: the size differs from the samples'");
  cl_kernel post = post_kernel();
  const size_t n = frame_pixels_;
  cl_command_queue q = runtime_.queue();
  const size_t display_bytes = round_up_div(n, 4) * 16;  // the post kernel writes whole quads
  const bool in_place =
      out.rgba8 && out.rgba8 == display_memory_ && display_bytes <= display_bytes_;
  if (in_place ? rgba8_memory_ != display_memory_ || rgba8_bytes_ != display_bytes_
               : rgba8_memory_ || rgba8_bytes_ < display_bytes) {
    rgba8_.reset();
    rgba8_ = in_place ? [&] {
      cl_int err = CL_SUCCESS;
      ClBufferHandle b(clCreateBuffer(runtime_.context(), CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR,
                                      display_bytes_, display_memory_, &err));
      cl_check(err, "clCreateBuffer", "placing the display image in the shared frame");
      return b;
    }()
                      : make_buffer(runtime_.context(), CL_MEM_WRITE_ONLY,
                                    std::max(display_bytes, buffer_pixels_ * 4 + 16),
                                    "the display image");
    rgba8_memory_ = in_place ? display_memory_ : nullptr;
    rgba8_bytes_ = in_place ? display_bytes_ : std::max(display_bytes, buffer_pixels_ * 4 + 16);
  }
  const cl_mem hdr = settings.denoise ? denoise(settings) : hdr_.get(), out8 = rgba8_.get();
  const cl_float exposure = settings.exposure;
  const cl_int quad_count = static_cast<cl_int>(round_up_div(n, 4));
  set_arg(post, 0, hdr);
  set_arg(post, 1, out8);
  set_arg(post, 2, exposure);
  set_arg(post, 3, quad_count);
  // Four pixels per work-item, in groups of a fixed size: left to itself PoCL picks a group size
  // from the global size and compiles a variant for each new one, which cost ~100 ms whenever
  // the explorer changed its resolution scale.
  const size_t post_local = 64;
  const size_t post_global = round_up_div(round_up_div(n, 4), post_local) * post_local;
  cl_check(
      clEnqueueNDRangeKernel(q, post, 1, nullptr, &post_global, &post_local, 0, nullptr, nullptr),
      "clEnqueueNDRangeKernel", "post-processing");

  const auto read = [&](cl_mem from, size_t bytes, void* to, const char* what_read) {
    cl_check(clEnqueueReadBuffer(q, from, CL_FALSE, 0, bytes, to, 0, nullptr, nullptr),
             "clEnqueueReadBuffer", what_read);
  };
  if (in_place) {
    // Mapping a CL_MEM_USE_HOST_PTR buffer makes the host memory current (no copy on PoCL).
    cl_int err = CL_SUCCESS;
    void* mapped =
        clEnqueueMapBuffer(q, out8, CL_FALSE, CL_MAP_READ, 0, n * 4, 0, nullptr, nullptr, &err);
    cl_check(err, "clEnqueueMapBuffer", "reading the image");
    cl_check(clEnqueueUnmapMemObject(q, out8, mapped, 0, nullptr, nullptr),
             "clEnqueueUnmapMemObject", "reading the image");
  } else {
    read(out8, n * 4, out.rgba8, "reading the image");
  }
  if (what != Readback::Display) {
    read(steps_.get(), n * 4, out.steps, "reading DE step counts");
    read(status_.get(), n, out.ray_status, "reading ray status");
  }
  std::vector<float> factors;
  if (what == Readback::Everything) {
    factors.resize(n * 2);
    read(hdr, n * 16, out.linear_rgba, "reading the linear image");
    read(depth_.get(), n * 4, out.depth, "reading depths");
    read(factors_.get(), n * 8, factors.data(), "reading occlusion and shadow factors");
    read(normal_.get(), n * 12, out.normal, "reading normals");
    read(albedo_.get(), n * 12, out.albedo, "reading albedos");
  }
  cl_check(clFinish(q), "clFinish", "reading back the frame");
  if (what == Readback::Everything) {
    for (size_t i = 0; i < n; ++i) {
      out.occlusion[i] = factors[2 * i];
      out.shadow[i] = factors[2 * i + 1];
    }
  }
  return {last_lanes_, last_precision_};
}

cl_kernel Renderer::denoise_kernel(const RenderSettings& settings) {
  if (settings.window.full_width_px > 0)
    throw std::invalid_argument(
        "render.denoise filters the whole picture, and this is a window of it (a poster's band "
        "or an MPI rank's share): render it whole, or without render.denoise");
  if (last_outputs_ != Readback::Everything)
    throw std::logic_error("Renderer::denoise: the samples did not write the guiding passes");
  if (static_cast<size_t>(settings.width_px) * settings.height_px != frame_pixels_)
    throw std::logic_error("Renderer::denoise: the size differs from the samples'");
  static const std::string source = std::string(kernel_source("denoise.cl"));
  cl_kernel k =
      runtime_.kernel(runtime_.program(source, "-cl-std=CL1.2", "the denoiser"), "fr_denoise");
  for (auto& b : denoised_)
    if (!b)
      b = make_buffer(runtime_.context(), CL_MEM_READ_WRITE,
                      round_up_div(buffer_pixels_, 4) * 4 * 4 * sizeof(float), "the denoiser");
  return k;
}

cl_mem Renderer::enqueue_denoise_pass(cl_kernel k, const RenderSettings& settings, int pass,
                                      RowBand rows) {
  const cl_int width = settings.width_px, height = settings.height_px;
  const cl_float angle = last_pixel_angle_rad_;
  const size_t local[2] = {8, 8};
  // A band's rows start at a multiple of 16, so of the groups' 8 (render_settings.hpp).
  const size_t offset[2] = {0, static_cast<size_t>(rows.first_row_px)};
  const size_t global[2] = {round_up_div(static_cast<size_t>(width), 8) * 8,
                            round_up_div(static_cast<size_t>(rows.rows_px), 8) * 8};
  // Five passes, taps 1 to 16 pixels apart; the colour's tolerance halves each pass (Dammertz
  // et al.), so the wide passes keep what the narrow ones left as an edge.
  const cl_mem from = pass == 0 ? hdr_.get() : denoised_[(pass - 1) % 2].get();
  const cl_mem to = denoised_[pass % 2].get();
  const cl_int step = 1 << pass, first = pass == 0, last = pass == kDenoisePasses - 1;
  const cl_float color_sigma = 0.5f / static_cast<float>(1 << pass);
  set_arg(k, 0, from);
  set_arg(k, 1, to);
  set_arg(k, 2, normal_.get());
  set_arg(k, 3, albedo_.get());
  set_arg(k, 4, depth_.get());
  set_arg(k, 5, width);
  set_arg(k, 6, height);
  set_arg(k, 7, step);
  set_arg(k, 8, angle);
  set_arg(k, 9, color_sigma);
  set_arg(k, 10, first);
  set_arg(k, 11, last);
  cl_check(
      clEnqueueNDRangeKernel(runtime_.queue(), k, 2, offset, global, local, 0, nullptr, nullptr),
      "clEnqueueNDRangeKernel", "the denoiser");
  return to;
}

void Renderer::denoise_rows(const RenderSettings& settings, int pass, RowBand rows) {
  const int h = settings.height_px;
  if (rows.rows_px == 0) rows = RowBand{0, h};
  const int end_row = rows.first_row_px + rows.rows_px;
  if (pass != denoise_pass_ || rows.first_row_px != denoise_next_row_ || rows.rows_px < 0 ||
      end_row > h || (end_row != h && rows.rows_px % kRowBandAlign != 0))
    throw std::logic_error("Renderer::denoise_rows: pass " + std::to_string(pass) + ", rows " +
                           std::to_string(rows.first_row_px) + " to " + std::to_string(end_row) +
                           " of " + std::to_string(h) + ", where pass " +
                           std::to_string(denoise_pass_) + " from row " +
                           std::to_string(denoise_next_row_) + " comes next");
  enqueue_denoise_pass(denoise_kernel(settings), settings, pass, rows);
  denoise_next_row_ = end_row;
  if (denoise_next_row_ == h) {
    ++denoise_pass_;
    denoise_next_row_ = 0;
  }
}

cl_mem Renderer::denoise(const RenderSettings& settings) {
  const cl_kernel k = denoise_kernel(settings);
  if (denoise_pass_ == kDenoisePasses) return denoised_[(kDenoisePasses - 1) % 2].get();
  if (denoise_pass_ != 0 || denoise_next_row_ != 0)
    throw std::logic_error("Renderer::denoise: denoise_rows stopped half-way");
  cl_mem result = nullptr;
  for (int pass = 0; pass < kDenoisePasses; ++pass)
    result = enqueue_denoise_pass(k, settings, pass, RowBand{0, settings.height_px});
  return result;
}

EvalCounts Renderer::eval_counts() {
  std::vector<uint32_t> words(kCountWords, 0);
  if (counted_samples_ > 0)
    cl_check(clEnqueueReadBuffer(runtime_.queue(), counts_.get(), CL_TRUE, 0, kCountBytes,
                                 words.data(), 0, nullptr, nullptr),
             "clEnqueueReadBuffer", "reading the DE counters");
  return sum_eval_counts(words, last_lanes_, frame_pixels_, counted_samples_);
}

FrameView view_of(const FrameImage& image) {
  FrameView v;
  v.width_px = image.width_px;
  v.height_px = image.height_px;
  v.lanes = image.lanes;
  v.precision = image.precision;
  v.rgba8 = image.rgba8.empty() ? nullptr : image.rgba8.data();
  const size_t n = v.pixel_count();
  v.steps = image.steps.size() == n && n > 0 ? image.steps.data() : nullptr;
  v.ray_status = image.ray_status.size() == n && n > 0 ? image.ray_status.data() : nullptr;
  v.depth = image.depth.size() == n && n > 0 ? image.depth.data() : nullptr;
  v.linear_rgba = image.linear_rgba.size() == 4 * n && n > 0 ? image.linear_rgba.data() : nullptr;
  return v;
}

RayCounts count_rays(const FrameImage& image) {
  return count_rays(view_of(image));
}

RayCounts count_rays(const FrameView& frame) {
  RayCounts c;
  if (!frame.ray_status) return c;
  const size_t n = frame.pixel_count();
  for (size_t i = 0; i < n; ++i) switch (static_cast<RayStatus>(frame.ray_status[i])) {
      case RayStatus::Miss:
        ++c.miss;
        break;
      case RayStatus::Hit:
        ++c.hit;
        break;
      case RayStatus::OutOfSteps:
        ++c.out_of_steps;
        break;
      case RayStatus::Inside:
        ++c.inside;
        break;
    }
  return c;
}

}  // namespace fr
