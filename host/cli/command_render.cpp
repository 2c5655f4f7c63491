#include "cli/commands.hpp"
#include "cli/prepared_scene.hpp"
#include "cli/progress.hpp"
#include "cli/watchdog.hpp"
#include "image/exr_write.hpp"
#include "image/png_write.hpp"
#include "image/poster.hpp"
#include "io/atomic_file.hpp"
#include "render/camera.hpp"
#include "render/memory_budget.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>

#include <sys/stat.h>
#include <unistd.h>
#include <chrono>
#include <filesystem>
#include <ostream>
#include <stdexcept>

namespace fr {
namespace {

// How the primary rays ended, and the warnings a user must see: many rays out of steps, a camera
// inside the solid, surface detail finer than float resolves.
void report_rays(const FrameImage& image, const fr_camera& camera, const RenderSettings& settings,
                 std::ostream& out) {
  const RayCounts rays = count_rays(image);
  const size_t total = image.ray_status.size();
  auto percent = [&](size_t n) { return 100.0 * double(n) / double(std::max<size_t>(total, 1)); };
  out << "rays: " << rays.hit << " hit, " << rays.miss << " missed, " << rays.out_of_steps
      << " out of steps, " << rays.inside << " started inside the surface\n";
  if (percent(rays.out_of_steps) > kOutOfStepsWarnPercent)
    spdlog::warn(
        "{:.2f}% of rays ran out of steps (render.max_steps = {}); each is shaded at its closest "
        "approach or as a miss; raise render.max_steps",
        percent(rays.out_of_steps), settings.max_steps);
  if (rays.inside > 0 && rays.inside == total)
    spdlog::warn(
        "the camera is inside the surface: every ray starts inside the solid and is black");
  if (image.precision == Precision::Float) {
    const CameraRays camera_rays = make_camera_rays(camera, image.width_px, image.height_px);
    const size_t fine = pixels_below_float_resolution(image.depth, camera_rays);
    if (fine > 0)
      spdlog::warn(
          "{:.2f}% of surface pixels are finer than float can resolve there; use --precision "
          "double",
          percent(fine));
  }
}

// A size over poster_band_pixels: rendered a band of rows at a time and streamed to the PNG or
// EXR file (image/poster.hpp), with a progress bar on a terminal.
int render_in_bands(const PreparedScene& p, const std::string& out_file, std::ostream& report,
                    std::ostream& err) {
  const int width = p.render.width_px, height = p.render.height_px;
  RenderSettings band = p.render;
  const uint64_t band_pixels = poster_band_pixels(out_file);
  band.height_px = poster_band_rows(width, height, band_pixels);
  check_memory(band, p.device, is_exr_file_name(out_file));
  ClRuntime runtime(p.device);
  // The watchdog guards each band: a poster may take longer than render.watchdog_s in all.
  Watchdog watchdog(p.render.watchdog_s, "rendering scene '" + p.scene->info.id + "'");
  const auto start = std::chrono::steady_clock::now();
  Progress progress(err, "band", (height + band.height_px - 1) / band.height_px);
  const PosterResult r = render_poster(runtime, p.scene->info, p.state, p.render, out_file,
                                       band_pixels, [&](int done, int) {
                                         watchdog.kick();
                                         progress.update(done);
                                       });
  watchdog.stop();
  progress.finish();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  report << "rendered " << p.scene->info.id << " " << width << "x" << height << " in " << r.bands
         << " bands on " << p.device.name << " (lanes " << r.lanes << ", "
         << precision_name(r.precision) << "): " << static_cast<int>(seconds() * 1000)
         << " ms; wrote " << out_file << "\n";
  report << "rays: " << r.rays.hit << " hit, " << r.rays.miss << " missed, " << r.rays.out_of_steps
         << " out of steps, " << r.rays.inside << " started inside the surface\n";
  const double total = static_cast<double>(width) * height;
  if (100.0 * r.rays.out_of_steps / total > kOutOfStepsWarnPercent)
    spdlog::warn(
        "{:.2f}% of rays ran out of steps (render.max_steps = {}); each is shaded at its closest "
        "approach or as a miss; raise render.max_steps",
        100.0 * r.rays.out_of_steps / total, p.render.max_steps);
  return 0;
}

std::vector<OptionSpec> render_option_specs() {
  auto specs = scene_option_specs();
  specs.push_back({"out", "FILE", false,
                   "PNG file to write (default fractalis.png); FILE.exr: OpenEXR, linear, with "
                   "passes"});
  specs.push_back({"path", "FILE", false,
                   "camera path (TOML keyframes): the view and parameters at --time (default: "
                   "its first keyframe); --eye, --param and the like still override"});
  specs.push_back({"counts", nullptr, false,
                   "also report where the DE evaluations went, per stage (a counting kernel:\n"
                   "                                 slower; the picture is the same)"});
  specs.push_back({"help", nullptr, false, "show this help"});
  return specs;
}

// The output file, checked before rendering, so a typo in the folder costs nothing.
void check_render_output(const std::string& out_file) {
  check_output_file("--out", out_file);
  if (!is_exr_file_name(out_file)) return;
  struct stat st {};
  if (stat(out_file.c_str(), &st) == 0 && (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)))
    throw UsageError("--out " + out_file +
                     ": an EXR file cannot go to a pipe or device (OpenEXR seeks back to index "
                     "its scanlines)");
}

// An image that fits in one piece: rendered under the watchdog, written atomically, reported.
void render_whole(PreparedScene& p, const std::string& out_file, std::ostream& report) {
  check_memory(p.render, p.device, true);
  ClRuntime runtime(p.device);
  Renderer renderer(runtime);
  using clock = std::chrono::steady_clock;
  auto ms_since = [](clock::time_point t) {
    return std::chrono::duration<double, std::milli>(clock::now() - t).count();
  };
  // Preparing runs the DE too (choosing the precision probes it), so both are watched.
  Watchdog watchdog(p.render.watchdog_s, "rendering scene '" + p.scene->info.id + "'");
  const auto build_start = clock::now();
  renderer.prepare(p.scene->info, p.state, p.render);
  const double build_ms = ms_since(build_start);
  watchdog.kick();
  const auto render_start = clock::now();
  FrameImage image = renderer.render(p.scene->info, p.state, p.render, true);
  const double render_ms = ms_since(render_start);
  watchdog.stop();
  std::string error;
  if (is_exr_file_name(out_file)
          ? !write_exr_atomic(out_file, image, &error)
          : !write_png_atomic(out_file, image.width_px, image.height_px, image.rgba8, &error))
    throw std::runtime_error(error);
  report << "rendered " << p.scene->info.id << " " << image.width_px << "x" << image.height_px
         << " on " << p.device.name << " (lanes " << image.lanes << ", "
         << precision_name(image.precision) << "): kernel build " << static_cast<int>(build_ms)
         << " ms, render " << static_cast<int>(render_ms) << " ms; wrote " << out_file << "\n";
  report_rays(image, p.state.camera, p.render, report);
  if (p.render.count_evaluations) report << format_eval_counts(renderer.eval_counts());
}

}  // namespace

int command_render(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto specs = render_option_specs();
  auto options = parse_options("render", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis render [--scene ID] [--size WxH] [--out FILE] [options]\n\n"
           "Renders one frame of a scene and writes it as a PNG (atomically: a temporary file,\n"
           "then a rename). Sizes go up to 65535 a side; over 8 M pixels the image is rendered\n"
           "a band of rows at a time and streamed to the PNG, in a band's memory.\n"
           "An --out ending in .exr gets an OpenEXR file instead: the linear HDR image with\n"
           "depth (Z), normal (N.x, N.y, N.z), albedo, DE steps and hit mask channels for\n"
           "compositing; large ones are rendered in bands like a PNG.\n\n"
        << format_options(specs) << "\nexample:\n"
        << "  fractalis render --scene mandelbulb --size 1280x720 --param power=6 --out bulb.png\n"
        << "  fractalis render --scene menger --size 1920x1080 --samples 4 --out sponge.exr\n";
    return 0;
  }
  const std::string out_file = options.get("out").value_or("fractalis.png");
  check_render_output(out_file);
  PreparedScene p = prepare_scene(options, kMaxPosterSide);
  p.render.count_evaluations = options.has("counts");
  update_scene(p, p.state.time_s);
  // `--out /dev/stdout | viewer`: the PNG is the output, the report goes to stderr.
  std::ostream& report = is_standard_output(out_file) ? err : out;
  if (static_cast<uint64_t>(p.render.width_px) * p.render.height_px >
      poster_band_pixels(out_file)) {
    if (p.render.count_evaluations)
      throw UsageError("--counts: not for images rendered in bands (over " +
                       std::to_string(poster_band_pixels(out_file)) + " pixels)");
    return render_in_bands(p, out_file, report, err);
  }
  render_whole(p, out_file, report);
  return 0;
}

}  // namespace fr
