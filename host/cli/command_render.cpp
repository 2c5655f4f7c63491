#include "cli/commands.hpp"
#include "cli/prepared_scene.hpp"
#include "cli/progress.hpp"
#include "cli/watchdog.hpp"
#include "image/band_writer.hpp"
#include "image/exr_write.hpp"
#include "image/frame_bytes.hpp"
#include "image/png_write.hpp"
#include "image/poster.hpp"
#include "io/atomic_file.hpp"
#include "mpi/mpi_world.hpp"
#include "mpi/shared_tasks.hpp"
#include "platform/files.hpp"
#include "render/camera.hpp"
#include "render/depth_iterations.hpp"
#include "render/kernel_assembly.hpp"
#include "render/memory_budget.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include <chrono>
#include <filesystem>
#include <ostream>
#include <stdexcept>

namespace fr {
namespace {

// How the primary rays ended, and the warnings a user must see: many rays out of steps, a camera
// inside the solid, surface detail finer than float resolves.
void report_rays(const FrameImage& image, const SceneInfo& info, const SceneState& state,
                 const RenderSettings& settings, RenderWorker& worker, std::ostream& out) {
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
  const CameraRays camera_rays = view_camera_rays(state, image.width_px, image.height_px,
                                                  settings.mirror_vertical, settings.pixel_corners);
  // Past double, whether the scene's pair estimate resolves these parameters (some are double
  // at some: the Mandelbulb at a fractional power).
  const auto pairs_resolve = [&] {
    const PairProbe probe = [&](const std::vector<std::array<float, 3>>& points,
                                const PairOrigin& origin) {
      return worker.probe_de(info, state.params, points, 1, Precision::DoubleDouble, &origin);
    };
    return pair_estimate_resolves_view(probe, state, camera_rays);
  };
  if (image.precision == Precision::DoubleDouble) {
    const size_t past_double =
        pixels_below_resolution(image.depth, camera_rays, Precision::Double);
    if (past_double > 0 && !pairs_resolve())
      spdlog::warn(
          "{:.2f}% of surface pixels are finer than double resolves, and scene '{}''s pair "
          "estimate is only double at these parameters (docs/deep_zoom.md): the picture there "
          "is not right",
          percent(past_double), info.id);
  }
  const size_t fine = pixels_below_resolution(image.depth, camera_rays, image.precision);
  if (fine == 0) return;
  const std::string share = fmt::format("{:.2f}% of surface pixels are finer than ", percent(fine));
  switch (image.precision) {
    case Precision::Float:
      spdlog::warn("{}float can resolve there; use --precision double (or auto)", share);
      break;
    case Precision::Double:
      if (has_pair_estimate(info) && pairs_resolve())
        spdlog::warn("{}double can resolve there; use --precision dd (or auto)", share);
      else if (has_pair_estimate(info))
        spdlog::warn(
            "{}double can resolve there, and scene '{}''s pair estimate is only double at "
            "these parameters (docs/deep_zoom.md): the picture there is not right",
            share, info.id);
      else
        spdlog::warn(
            "{}double can resolve there, and scene '{}' has no pair estimate "
            "(scene_de_dd): the picture there is not right",
            share, info.id);
      break;
    default:
      spdlog::warn(
          "{}double-double resolves (16 of its ulps, 2^-100 of the position): past the "
          "deepest view Fractalis renders",
          share);
  }
}

// An MPI job's ranks other than 0 (mpi/shared_tasks.hpp): render the bands rank 0 hands out and
// send them back, each under its own watchdog (waiting for rank 0 between bands is not
// rendering).
void serve_poster_bands(const PreparedScene& p, int band_rows, Readback passes) {
  std::optional<RenderSettings> whole;
  FrameImage band;
  const std::string rank = std::to_string(mpi_world().rank);
  serve_tasks([&](int b) {
    Watchdog watchdog(p.render.watchdog_s, "rendering scene '" + p.scene->info.id + "' (rank " +
                                               rank + ", band " + std::to_string(b) + ")");
    if (!whole) whole = poster_settings(*p.worker, p.scene->info, p.state, p.render);
    render_poster_band(*p.worker, p.scene->info, p.state, *whole, band_rows, b, passes, band);
    // A PNG needs the colours, and the report the rays' ends; the steps stay here.
    if (passes != Readback::Everything) band.steps.clear();
    std::vector<uint8_t> bytes;
    append_frame_bytes(band, bytes);
    return bytes;
  });
}

// Rank 0 of an MPI job: hands the bands out and writes them in order as they come back. The same
// bands as one process renders, so the same file.
PosterResult lead_poster_bands(const PreparedScene& p, const std::string& out_file, int band_rows,
                               Progress& progress) {
  const int width = p.render.width_px, height = p.render.height_px;
  PosterResult result;
  result.bands = (height + band_rows - 1) / band_rows;
  std::optional<BandWriter> writer;
  try {
    writer.emplace(out_file, width, height);
  } catch (...) {
    dismiss_ranks(1);
    throw;
  }
  std::vector<int> tasks(static_cast<size_t>(result.bands));
  for (int b = 0; b < result.bands; ++b) tasks[static_cast<size_t>(b)] = b;
  TaskSharing how;
  how.noun = "band";
  how.window = static_cast<size_t>(mpi_world().size);  // bands held here: memory stays bounded
  how.deadline_s = rank_task_deadline_s(p.render.watchdog_s);
  FrameImage band;
  lead_tasks(tasks, how, [&](int b, std::vector<uint8_t>& bytes) {
    size_t at = 0;
    read_frame_bytes(bytes, &at, band);
    const int rows = std::min(band_rows, height - b * band_rows);
    if (band.width_px != width || band.height_px != rows)
      throw std::runtime_error("band " + std::to_string(b) + " came back " +
                               std::to_string(band.width_px) + "x" +
                               std::to_string(band.height_px) + ", not " + std::to_string(width) +
                               "x" + std::to_string(rows));
    // Auto precision is decided on each rank; bands in different precisions would not match.
    if (b > 0 && band.precision != result.precision)
      throw std::runtime_error(
          "the ranks chose different precisions for the bands (machines that differ?); give "
          "--precision float or --precision double");
    result.precision = band.precision;
    result.lanes = band.lanes;
    writer->write_rows(band);
    add_ray_counts(band, result.rays);
    progress.update(b + 1);
  });
  writer->finish();
  return result;
}

// A poster rendered a band of rows at a time and streamed to the PNG or EXR file
// (image/poster.hpp), with a progress bar on a terminal; in an MPI job, by all its ranks.
int render_in_bands(const PreparedScene& p, const std::string& out_file, int band_rows,
                    std::ostream& report, std::ostream& err) {
  const int width = p.render.width_px, height = p.render.height_px;
  const MpiWorld& world = mpi_world();
  const auto start = std::chrono::steady_clock::now();
  Progress progress(err, "band", (height + band_rows - 1) / band_rows);  // rank 0's alone
  PosterResult r;
  if (world.shared() && world.rank != 0) {
    serve_poster_bands(p, band_rows, BandWriter::passes_for(out_file));
    return 0;
  } else if (world.shared()) {
    r = lead_poster_bands(p, out_file, band_rows, progress);
  } else {
    // The watchdog guards each band: a poster may take longer than render.watchdog_s in all.
    Watchdog watchdog(p.render.watchdog_s, "rendering scene '" + p.scene->info.id + "'");
    r = render_poster_in_rows(*p.worker, p.scene->info, p.state, p.render, out_file, band_rows,
                              [&](int done, int) {
                                watchdog.kick();
                                progress.update(done);
                              });
    watchdog.stop();
  }
  progress.finish();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  report << "rendered " << p.scene->info.id << " " << width << "x" << height << " in " << r.bands
         << (r.bands == 1 ? " band on " : " bands on ") << p.device.name << " (lanes " << r.lanes
         << ", " << precision_name(r.precision) << ")";
  if (world.shared()) report << " by " << rendering_ranks_text();
  report << ": " << static_cast<int>(seconds() * 1000) << " ms; wrote " << out_file << "\n";
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
  specs.push_back(
      {"band-rows", "N", false,
       "render in bands of N rows, streamed to the file (default: bands of 8 M pixels\n"
       "                                 over that size); in an MPI job the ranks share\n"
       "                                 the bands"});
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
  if (const std::string why = exr_unavailable_reason(); !why.empty())
    throw UsageError("--out " + out_file + ": " + why);
  const PathKind kind = examine_path(out_file).kind;
  if (kind == PathKind::Pipe || kind == PathKind::CharacterDevice)
    throw UsageError("--out " + out_file +
                     ": an EXR file cannot go to a pipe or device (OpenEXR seeks back to index "
                     "its scanlines)");
}

// An image that fits in one piece: rendered under the watchdog, written atomically, reported.
void render_whole(PreparedScene& p, const std::string& out_file, std::ostream& report) {
  check_memory(p.render, p.device, true);
  RenderWorker& renderer = *p.worker;
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
  if (!renderer.raised_iterations().empty())
    report << "for the view's depth (render.auto_iterations): "
           << describe_raised(renderer.raised_iterations()) << "\n";
  report_rays(image, p.scene->info, p.state, p.render, renderer, report);
  if (p.render.count_evaluations) report << format_eval_counts(renderer.eval_counts());
}

// One picture, checked before anything is rendered: the scene, the output, the bands.
struct RenderJob {
  PreparedScene p;
  int band_rows = 0;  // 0: the whole image at once
};

RenderJob plan_render(const ParsedOptions& options, const std::string& out_file) {
  // Rank 0 writes the file: other ranks of an MPI job, perhaps on machines without that folder,
  // do not look for it.
  if (mpi_world().rank == 0) check_render_output(out_file);
  RenderJob job{prepare_scene(options, kMaxPosterSide)};
  PreparedScene& p = job.p;
  p.render.count_evaluations = options.has("counts");
  update_scene(p, p.state.time_s);
  const uint64_t pixels = static_cast<uint64_t>(p.render.width_px) * p.render.height_px;
  if (const auto rows = options.get("band-rows"))
    job.band_rows = static_cast<int>(parse_integer("--band-rows", *rows, 1, kMaxPosterSide));
  else if (pixels > poster_band_pixels(out_file))
    job.band_rows =
        poster_band_rows(p.render.width_px, p.render.height_px, poster_band_pixels(out_file));
  if (job.band_rows > 0) {
    if (p.render.count_evaluations)
      throw UsageError("--counts: not for images rendered in bands (--band-rows, or over " +
                       std::to_string(poster_band_pixels(out_file)) + " pixels)");
    // The filter reads across any band's edge.
    if (p.render.denoise)
      throw UsageError("render.denoise: not for images rendered in bands (--band-rows, or over " +
                       std::to_string(poster_band_pixels(out_file)) +
                       " pixels); it filters the whole picture at once");
    RenderSettings band = p.render;
    band.height_px = std::min(job.band_rows, p.render.height_px);
    check_memory(band, p.device, is_exr_file_name(out_file));
  }
  return job;
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
  // Every rank of an MPI job reads the options and loads the scene; any that fails ends them all.
  RenderJob job = prepare_on_every_rank([&] { return plan_render(options, out_file); });
  PreparedScene& p = job.p;
  const int band_rows = job.band_rows;
  // `--out /dev/stdout | viewer`: the PNG is the output, the report goes to stderr.
  std::ostream& report = is_standard_output(out_file) ? err : out;
  if (band_rows > 0) return render_in_bands(p, out_file, band_rows, report, err);
  // One picture in one piece is rank 0's alone.
  if (mpi_world().rank != 0) return 0;
  if (mpi_world().shared())
    spdlog::info("one image in one piece renders on rank 0 alone; --band-rows N shares its bands");
  render_whole(p, out_file, report);
  return 0;
}

}  // namespace fr
