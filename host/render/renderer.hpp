// renderer.hpp — frames of a scene on an OpenCL device: assemble and build (cached) the scene's
// kernel, upload the frame constants and parameters, run the render kernel once per sample into
// a running mean, then the post kernel, and read back the image.
#pragma once

#include "scene/scene_data.hpp"

#include "render/cl_runtime.hpp"
#include "render/eval_counts.hpp"
#include "render/render_settings.hpp"

struct fr_frame_constants;  // kernels/frame_constants.h

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fr {

struct FrameImage {
  int width_px = 0;
  int height_px = 0;
  int lanes = 0;               // lane width the frame was rendered with
  std::vector<uint8_t> rgba8;  // tonemapped, sRGB, 4 bytes per pixel, rows top to bottom
  // Filled only when asked for (Readback), for the primary rays of the last sample; otherwise
  // left empty:
  std::vector<float> linear_rgba;  // linear HDR (the accumulated mean), 4 floats per pixel
  std::vector<float> depth;        // distance along the ray to the hit; +inf for a miss
  std::vector<float> steps;        // DE evaluations of the primary ray
  std::vector<float> occlusion;    // ambient-occlusion factor at the hit, in [0, 1]; 1 on a miss
  std::vector<float> shadow;       // first light's shadow factor at the hit, in [0, 1]
  std::vector<float> normal;       // unit surface normal at the hit, 3 floats; 0 for a miss
  std::vector<float> albedo;       // the surface's albedo (linear RGB) at the hit; 0 for a miss
  // Filled with the steps (DisplayAndSteps, Everything): each primary ray's RayStatus.
  std::vector<uint8_t> ray_status;
  Precision precision = Precision::Float;  // what the kernel ran in (Auto resolved)
};

// How each primary ray ended (kernels/march.cl's FR_RAY_*).
enum class RayStatus : uint8_t {
  Miss = 0,
  Hit = 1,
  OutOfSteps = 2,  // the step budget ended first: shaded at the best candidate point
  Inside = 3,      // started inside the solid: black
};

// Where Renderer::finish_into puts a frame's passes, width x height pixels each, laid out as
// FrameImage's vectors; a pointer is null for a pass that is not read back.
struct FramePassPointers {
  uint8_t* rgba8 = nullptr;
  float* steps = nullptr;
  uint8_t* ray_status = nullptr;
  float* linear_rgba = nullptr;
  float* depth = nullptr;
  float* occlusion = nullptr;
  float* shadow = nullptr;
  float* normal = nullptr;
  float* albedo = nullptr;
};

// Sizes `image`'s vectors for `what` at `width_px` x `height_px` (emptying the others) and
// returns pointers to them.
FramePassPointers size_frame_image(FrameImage& image, int width_px, int height_px, Readback what);

// A whole image from anything with Renderer's render_sample and finish (the renderer, the render
// worker): settings.samples samples, then the display image, and with `read_linear` every pass.
template <typename Frames>
FrameImage render_all_samples(Frames& frames, const SceneInfo& info, const SceneState& state,
                              const RenderSettings& settings, bool read_linear) {
  const Readback what = read_linear ? Readback::Everything : Readback::Display;
  for (int i = 0; i < std::max(1, settings.samples); ++i)
    frames.render_sample(info, state, settings, i, what);
  FrameImage image;
  frames.finish(settings, what, image);
  return image;
}

// A frame's display passes where they already lie (the render worker's shared frame, or a
// FrameImage), for a caller that shows a frame and lets it go (the explorer): no copy. Valid until
// the next call on whatever returned it.
struct FrameView {
  int width_px = 0;
  int height_px = 0;
  int lanes = 0;
  Precision precision = Precision::Float;
  const uint8_t* rgba8 = nullptr;       // as FrameImage's, width x height
  const float* steps = nullptr;         // null when not read back
  const uint8_t* ray_status = nullptr;  // null when not read back
  const float* depth = nullptr;         // null when not read back (Everything)
  const float* linear_rgba = nullptr;  // the accumulated mean; null when not read back (Everything)
  size_t pixel_count() const { return static_cast<size_t>(width_px) * height_px; }
};
// A view of `image` (its steps and ray status when it has them).
FrameView view_of(const FrameImage& image);

struct RayCounts {
  size_t miss = 0, hit = 0, out_of_steps = 0, inside = 0;
};
RayCounts count_rays(const FrameImage& image);
RayCounts count_rays(const FrameView& frame);  // none without ray status

// `render` warns when more than this percentage of primary rays ran out of steps.
constexpr double kOutOfStepsWarnPercent = 0.5;

class Renderer {
 public:
  explicit Renderer(ClRuntime& runtime);

  // Renders settings.samples samples of `state` and tonemaps their mean. Throws
  // KernelBuildError if the scene's kernel does not compile, ClError if the device fails.
  FrameImage render(const SceneInfo& info, const SceneState& state, const RenderSettings& settings,
                    bool read_linear = false);

  // Progressive rendering: adds sample `sample_index` (0 restarts the mean) to the accumulation,
  // then `finish` tonemaps what has accumulated so far into `image`, reusing its vectors'
  // storage (an interactive caller passes the same image every frame: no allocation, no page
  // faults). Fields that `what` does not ask for are emptied. The kernel writes only the passes
  // `outputs` names (writing all of them cost about 1.3 ms a 1280x720 frame here); `finish` may
  // not ask for more than the samples wrote (std::logic_error). `rows`: only those rows get the
  // sample (render_settings.hpp, RowBand; std::invalid_argument for a band that is not one).
  void render_sample(const SceneInfo& info, const SceneState& state, const RenderSettings& settings,
                     int sample_index, Readback outputs = Readback::Everything, RowBand rows = {});
  void finish(const RenderSettings& settings, Readback what, FrameImage& image);
  // `finish` into memory the caller owns (the render worker's shared frame): every pointer that
  // `what` names must hold width x height pixels of its pass. Returns the lanes and precision
  // the samples ran with; FrameImage's other fields.
  struct FinishedFrame {
    int lanes = 0;
    Precision precision = Precision::Float;
  };
  FinishedFrame finish_into(const RenderSettings& settings, Readback what,
                            const FramePassPointers& out);
  // The render worker: `finish_into` whose out.rgba8 is `memory` (the shared frame, `bytes` long)
  // has the post stage write the display image straight into it, the device using it as the
  // buffer itself (CL_MEM_USE_HOST_PTR; on PoCL no copy at all). Null: the device's own buffer
  // and a read-back.
  void set_display_memory(uint8_t* memory, size_t bytes);

  // The denoiser (settings.denoise) in steps, so that its second or so at 1280x720 on a CPU does
  // not hold a caller that has input to answer (the explorer's filtered preview): pass `pass` of
  // kDenoisePasses over `rows` of the accumulated picture (RowBand, as render_sample's). The
  // passes come in order, each covering every row, top to bottom, before the next
  // (std::logic_error otherwise); once all have, `finish` with settings.denoise reads their
  // result rather than filtering again. A new sample starts over.
  static constexpr int kDenoisePasses = 5;
  void denoise_rows(const RenderSettings& settings, int pass, RowBand rows);

  // The DE evaluations of the samples rendered since the last sample 0, when they were rendered
  // with settings.count_evaluations (otherwise all zero). Waits for the device.
  EvalCounts eval_counts();

  // The lane width a frame of this scene with these settings uses on this device.
  int lanes_for(const SceneInfo& info, const RenderSettings& settings) const;

  // Builds (or finds in the cache) the kernel a frame with these settings runs, deciding Auto
  // precision as the first sample would; returns the precision. Lets a caller time the kernel
  // build apart from the render.
  Precision prepare(const SceneInfo& info, const SceneState& state, const RenderSettings& settings);

 private:
  void ensure_buffers(size_t pixel_count);
  // The render program for `settings` (precision already resolved; kernels fr_render and, with
  // the cone pre-pass, fr_cone) at *lanes; *description names it. Where the device chose a wide
  // width and the scene's code does not build at it, builds at kPacketLanes, sets *lanes to it
  // and remembers the scene (narrow_scenes_).
  cl_program render_program(const SceneInfo& info, const SceneState& state,
                            const RenderSettings& settings, int* lanes, std::string* description);
  cl_kernel post_kernel();
  // Auto's precision for a frame (resolve_precision), moved from double to float where the cone
  // pre-pass shows every primary hit far enough off for float (cone_hit_bound); other
  // precisions as they are.
  Precision choose_precision(const SceneInfo& info, const SceneState& state,
                             const RenderSettings& requested);
  // The whole frame's cone pre-pass, run with `settings` (precision resolved): the least start
  // of a block whose rays can hit (none is hit nearer), +inf when none can, 0 without the pass.
  double cone_hit_bound(const SceneInfo& info, const SceneState& state,
                        const RenderSettings& settings);
  // Uploads a sample's frame constants and scene parameters (the buffers constants_ and
  // params_) and returns the constants; *environment: the kernel's panorama argument.
  fr_frame_constants upload_frame(const SceneInfo& info, const SceneState& state,
                                  const RenderSettings& settings, int sample_index,
                                  cl_mem* environment);
  // Enqueues the cone pre-pass (kernels/cone.cl) of `program` at `lanes` over the blocks of
  // `rows` (a whole band, not {0, 0}), into cone_t_ and cone_ao_ (grown to fit).
  void enqueue_cone(cl_program program, const fr_frame_constants& fc, int lanes, RowBand rows,
                    const std::string& description);
  // The panorama of render.environment on the device (read and uploaded when the path changes;
  // std::runtime_error naming the file when it cannot be read), or a placeholder without one;
  // sets environment_width_px_ and environment_height_px_.
  cl_mem environment_memory(const RenderSettings& settings);
  // Filters the accumulated picture (render.denoise), unless denoise_rows did, and returns the
  // buffer holding the result.
  cl_mem denoise(const RenderSettings& settings);
  // Checks that the picture may be filtered (the whole, its guides written) and makes the
  // filter's buffers; returns its kernel.
  cl_kernel denoise_kernel(const RenderSettings& settings);
  // Enqueues pass `pass` over `rows`; returns the buffer it writes.
  cl_mem enqueue_denoise_pass(cl_kernel kernel, const RenderSettings& settings, int pass,
                              RowBand rows);

  ClRuntime& runtime_;
  size_t buffer_pixels_ = 0;  // capacity of the buffers
  size_t frame_pixels_ = 0;   // pixels of the frame being rendered
  int last_lanes_ = 0;
  // Scenes (id and a hash of their code) that did not build at a wide width: they render at
  // kPacketLanes, without a failing build each frame.
  std::set<std::pair<std::string, size_t>> narrow_scenes_;
  Readback last_outputs_ = Readback::Everything;  // what the last sample's kernel wrote
  Precision last_precision_ = Precision::Float;
  // The device's double-double self-test (render/dd_selftest.hpp), run before its first pair
  // frame: "" when it passed, else why pairs are refused there.
  std::optional<std::string> pairs_refused_;
  ClBufferHandle constants_, params_, hdr_, depth_, steps_, factors_, status_, normal_, albedo_,
      rgba8_;
  size_t params_bytes_ = 0;
  ClBufferHandle counts_;  // uint[FR_COUNT_SLOTS][FR_COUNT_CELLS][2], kernels/eval_counts.cl
  uint8_t* display_memory_ = nullptr;  // set_display_memory
  size_t display_bytes_ = 0;
  uint8_t* rgba8_memory_ = nullptr;  // the host memory rgba8_ lies in, when it does
  size_t rgba8_bytes_ = 0;           // rgba8_'s size
  ClBufferHandle cone_t_, cone_ao_;  // per cone block (kernels/cone.cl)
  ClBufferHandle denoised_[2];       // the denoiser's passes (kernels/denoise.cl), like hdr_
  // denoise_rows's progress since the last sample: the pass under way and its next row.
  int denoise_pass_ = 0, denoise_next_row_ = 0;
  ClBufferHandle environment_, no_environment_;  // environment_memory
  std::string environment_path_;  // the panorama in environment_: path, size, time of change
  int environment_width_px_ = 0, environment_height_px_ = 0;
  float last_pixel_angle_rad_ = 0;  // of the last sample's camera, for the denoiser
  size_t cone_blocks_ = 0;          // capacity of the cone buffers
  int counted_samples_ = 0;         // samples counted into counts_ since it was last cleared
};

}  // namespace fr
