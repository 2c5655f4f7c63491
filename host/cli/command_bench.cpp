#include "app/explore_bench.hpp"
#include "bench/bench_report.hpp"
#include "cli/commands.hpp"
#include "cli/explorer_setup.hpp"
#include "cli/watchdog.hpp"
#include "io/atomic_file.hpp"
#include "io/echo.hpp"
#include "render/kernel_assembly.hpp"
#include "render/renderer.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <stdexcept>

namespace fr {
namespace {

int bench_explore(ParsedOptions options, std::ostream& out,
                  std::ostream& /*err: messages go to spdlog*/) {
  if (!options.has("size")) options.values["size"] = {"1280x720"};
  if (!options.has("scene")) options.values["scene"] = {"mandelbulb"};
  const int frames =
      static_cast<int>(parse_integer("--frames", options.get("frames").value_or("120"), 1, 100000));
  ExplorerSetup setup = prepare_explorer(options, /*settings_problems_are_errors=*/true);
  Explorer& explorer = *setup.explorer;
  const RenderSettings& render = setup.settings.render;
  // --error keeps every moving frame (up to the window's size each) until the flight ends.
  const double frame_bytes = 4.0 * render.width_px * render.height_px;
  constexpr double kKeptBytes = 4.0 * (uint64_t{1} << 30);
  // SSIM's window is 11x11 pixels (bench/image_error.hpp): said before the flight, not after.
  if (options.has("error") && (render.width_px < kSsimWindowPx || render.height_px < kSsimWindowPx))
    throw UsageError("--error judges frames with an " + std::to_string(kSsimWindowPx) + "x" +
                     std::to_string(kSsimWindowPx) + " window: --size " +
                     std::to_string(render.width_px) + "x" + std::to_string(render.height_px) +
                     " is smaller");
  if (options.has("error") && frames * frame_bytes > kKeptBytes) {
    char what[256];
    std::snprintf(what, sizeof what,
                  "--error keeps each moving frame until the flight ends: --frames %d at %dx%d "
                  "could take %.1f GiB; at most %d frames at this size",
                  frames, render.width_px, render.height_px, frames * frame_bytes / (1 << 30),
                  static_cast<int>(kKeptBytes / frame_bytes));
    throw UsageError(what);
  }
  explorer.set_count_evaluations(options.has("counts"));
  if (const auto lattice = options.get("lattice")) {
    // A fixed lattice: what reuse shows at that share of fresh pixels, whatever the frame rate.
    const auto strides = parse_size("--lattice", *lattice, 5);
    if (!setup.settings.explorer.temporal)
      throw UsageError("--lattice: only with temporal reuse (explorer.temporal = true)");
    explorer.fix_lattice(strides[0], strides[1]);
  }
  // Warm-up: build the kernels the flight uses (render and DE probe), untimed.
  explorer.render(render.width_px, render.height_px);
  ExploreBenchOptions bench;
  bench.moving_frames = frames;
  bench.measure_error = options.has("error");
  if (const auto save = options.get("save-frame")) {
    // N:PREFIX, said before the flight rather than after it.
    const size_t colon = save->find(':');
    if (colon == std::string::npos || colon + 1 == save->size())
      throw UsageError("--save-frame: expected N:PREFIX (for example 60:flight-), got '" + *save +
                       "'");
    bench.save_frame =
        static_cast<int>(parse_integer("--save-frame", save->substr(0, colon), 0, frames - 1));
    bench.save_prefix = save->substr(colon + 1);
    // A folder that is not there is said now, not after minutes of flight.
    check_output_file("--save-frame", bench.save_prefix + "shown.png");
    check_output_file("--save-frame", bench.save_prefix + "reference.png");
  }
  const ExploreBenchResult r =
      run_explore_bench(explorer, render.width_px, render.height_px, bench);
  const bool path = setup.settings.render.integrator == Integrator::Path;
  char line[512];
  std::snprintf(
      line, sizeof line,
      "explore bench: scene %s, window %dx%d, %d frames flying\n"
      "moving: median %.2f ms (%.1f fps), p95 %.2f ms, min %.2f ms, max %.2f ms, mean "
      "resolution scale %.2f\n"
      "stopped: full resolution after %.2f s, full quality (%d %ssamples) after %.2f s, %d "
      "frames, the longest %.0f ms\n",
      explorer.current().scene->info.id.c_str(), render.width_px, render.height_px, frames,
      r.moving.p50_ms, 1000.0 / r.moving.p50_ms, r.moving.p95_ms, r.moving.min_ms, r.moving.max_ms,
      r.mean_resolution_scale, r.seconds_to_full_resolution,
      path ? setup.settings.explorer.path_samples : setup.settings.explorer.full_quality_samples,
      path ? "path-traced " : "", r.seconds_to_full_quality, r.refine_frames,
      r.refine_frame_max_ms);
  out << line;
  if (r.temporal_frames > 0) {
    const double px = double(render.width_px) * render.height_px;
    std::snprintf(line, sizeof line,
                  "temporal reuse in %d of %d moving frames; pixels per frame: %.0f traced "
                  "(%.1f%%), %.0f reused (%.1f%%), %.0f filled (%.1f%%), %.0f rejected; median "
                  "%.2f ms tracing, %.2f ms carrying\n",
                  r.temporal_frames, frames, r.mean_fresh_px, 100 * r.mean_fresh_px / px,
                  r.mean_reused_px, 100 * r.mean_reused_px / px, r.mean_filled_px,
                  100 * r.mean_filled_px / px, r.mean_rejected_px, r.median_trace_ms,
                  r.median_compose_ms);
    out << line;
  }
  if (explorer.count_evaluations())
    out << "while moving, over all the moving frames' pixels:\n"
        << format_eval_counts(r.moving_counts);
  if (bench.measure_error) {
    const DisplayedError& e = r.moving_error;
    std::snprintf(line, sizeof line,
                  "shown while moving, against fully traced frames (%d frames): mean absolute "
                  "error %.4f (worst frame %.4f), SSIM %.4f (worst frame %.4f)\n",
                  e.frames, e.mean_mae, e.max_mae, e.mean_ssim, e.min_ssim);
    out << line;
  }
  out << "device " << setup.worker->device().name << "\n";
  return 0;
}

std::vector<OptionSpec> bench_option_specs() {
  auto specs = scene_option_specs();
  specs.push_back({"frames", "N", false, "timed frames per run (default 30)"});
  specs.push_back({"runs", "N", false, "runs of the whole path (default 3)"});
  specs.push_back({"duration", "SECONDS", false, "scene time one run covers (default 10)"});
  specs.push_back(
      {"path", "FILE", false,
       "camera path to fly (default for the benchmark scene: its route,\n"
       "                                 config/paths/benchmark.toml; others: their own "
       "animation)"});
  specs.push_back({"json", "FILE", false, "also write the report as JSON (atomically)"});
  specs.push_back(
      {"explore", nullptr, false,
       "measure the explorer instead: a scripted fly-through at --size (default\n"
       "                                 1280x720), fps while moving, time to full quality"});
  specs.push_back(
      {"counts", nullptr, false,
       "with --explore: also count the DE evaluations of the frames while moving\n"
       "                                 (a counting kernel: its times are not comparable)"});
  specs.push_back(
      {"error", nullptr, false,
       "with --explore: also judge each moving frame as shown (stretched to the\n"
       "                                 window) against a fully traced frame of the same camera"});
  specs.push_back({"lattice", "SXxSY", false,
                   "with --explore and explorer.temporal: trace every SX-th column of every\n"
                   "                                 SY-th row while moving (1 to 5), not what the "
                   "frame rate asks"});
  specs.push_back({"save-frame", "N:PREFIX", false,
                   "with --explore --error: write moving frame N (from 0) as shown and its\n"
                   "                                 reference to PREFIXshown.png and "
                   "PREFIXreference.png"});
  specs.push_back({"help", nullptr, false, "show this help"});
  return specs;
}

// A benchmark, checked before it runs: the scene, its path, how many frames, where JSON goes.
struct BenchJob {
  PreparedScene p;
  std::optional<CameraPath> path;
  int frames = 30, runs = 3;
  double duration_s = 10;
  std::optional<std::string> json_file;
};

BenchJob plan_bench(ParsedOptions& options) {
  BenchJob job;
  job.frames =
      static_cast<int>(parse_integer("--frames", options.get("frames").value_or("30"), 1, 100000));
  job.runs = static_cast<int>(parse_integer("--runs", options.get("runs").value_or("3"), 1, 1000));
  job.duration_s = parse_finite("--duration", options.get("duration").value_or("10"));
  if (!(job.duration_s >= 0))
    throw UsageError("--duration: expected seconds >= 0, got " + echo(*options.get("duration")));
  if (!options.has("scene") && !options.has("preset")) options.values["scene"] = {"benchmark"};
  if (!options.has("path") && options.get("scene") == "benchmark")
    options.values["path"] = {shipped_path_file("benchmark.toml").string()};
  job.json_file = options.get("json");
  // Checked before the benchmark runs, not after.
  if (job.json_file) check_output_file("--json", *job.json_file);
  job.p = prepare_scene(options);
  if (auto file = options.get("path")) job.path = load_path_option(job.p.scene->info, *file);
  check_memory(job.p.render, job.p.device, false);
  return job;
}

// The warm-up frame, the timed runs, then one run again with the counting kernel (untimed).
BenchReport run_bench(BenchJob& job, const ParsedOptions& options) {
  PreparedScene& p = job.p;
  RenderWorker& renderer = *p.worker;
  Watchdog watchdog(p.render.watchdog_s, "a frame of scene '" + p.scene->info.id + "'");
  Precision ran_in = p.render.precision;  // what the last frame ran in (auto resolved)
  int ran_lanes = 0;                      // and at what lane width
  auto frame = [&](double time_s) {
    if (job.path) {  // run time t is the path's start + t (clamped to its end)
      const PathSample sample =
          sample_camera_path(*job.path, p.scene->info, job.path->start_s() + time_s);
      p.state.camera = sample.camera;
      p.state.camera_lo = sample.camera_lo;
      p.state.params = sample.params;
      apply_scene_overrides(p.scene->info, options, p.state, p.preset);
    }
    update_scene(p, time_s);
    const auto& image = renderer.render(p.scene->info, p.state, p.render);
    ran_in = image.precision;
    ran_lanes = image.lanes;
    watchdog.kick();
  };
  using clock = std::chrono::steady_clock;
  const auto origin = clock::now();
  auto now_ms = [&] {
    return std::chrono::duration<double, std::milli>(clock::now() - origin).count();
  };
  BenchReport report;
  const double warm_start = now_ms();
  frame(0);  // builds the kernel
  report.kernel_build_ms = now_ms() - warm_start;
  std::vector<double> all;
  const double wall_start = now_ms();
  for (int run = 0; run < job.runs; ++run) {
    auto times = time_frames(
        job.frames, [&](int i) { frame(job.duration_s * i / job.frames); }, now_ms);
    report.run_mean_ms.push_back(summarize_frames(times).mean_ms);
    all.insert(all.end(), times.begin(), times.end());
  }
  report.wall_s = (now_ms() - wall_start) / 1000.0;
  // Where the evaluations went: the frames of one run again, with a counting kernel (untimed).
  p.render.count_evaluations = true;
  for (int i = 0; i < job.frames; ++i) {
    frame(job.duration_s * i / job.frames);
    add_eval_counts(report.counts, renderer.eval_counts());
  }
  p.render.count_evaluations = false;
  report.stats = summarize_frames(all);
  // Auto says what it chose (for the last frame: a path may change it on the way).
  report.precision = p.render.precision == Precision::Auto
                         ? std::string("auto: ") + precision_name(ran_in)
                         : precision_name(p.render.precision);
  report.lanes = ran_lanes;
  return report;
}

// The rest of the report (what ran, where), then the text and, with --json, the file.
void report_bench(const BenchJob& job, BenchReport& report, std::ostream& out, std::ostream& err) {
  const PreparedScene& p = job.p;
  report.scene_id = p.scene->info.id;
  report.scene_version = p.scene->info.version;
  report.width_px = p.render.width_px;
  report.height_px = p.render.height_px;
  report.stages = stage_names(make_kernel_config(p.scene->info, p.render, report.lanes).stages);
  report.integrator = enum_name(p.render.integrator);
  report.samples_per_frame = std::max(1, p.render.samples);
  report.runs = job.runs;
  report.frames_per_run = job.frames;
  report.path_duration_s = job.duration_s;
  if (job.path) report.camera_path = job.path->file;
  report.system = read_system_info(p.device);
  std::ostream& text = job.json_file && is_standard_output(*job.json_file) ? err : out;
  text << format_bench_text(report);
  if (!job.json_file) return;
  std::string error;
  if (!write_file_atomic(*job.json_file, format_bench_json(report), &error))
    throw std::runtime_error(error);
  text << "wrote " << *job.json_file << "\n";
}

}  // namespace

int command_bench(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto specs = bench_option_specs();
  auto options = parse_options("bench", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis bench [--scene ID] [--size WxH] [--frames N] [--runs N] [--duration "
           "S]\n"
           "                       [--json FILE] [options]\n\n"
           "Renders a scene along its animation for a fixed number of frames, several times,\n"
           "after one untimed warm-up frame that builds the kernel, and reports frame times\n"
           "(min, max, average, p50, p95), fps, and the system it ran on. Without --scene it runs\n"
           "the benchmark scene along its fixed route (the camera path "
           "config/paths/benchmark.toml);\n"
           "--path flies any scene along a path. Each frame is the whole loop: camera path,\n"
           "scene update, render, tonemap, read-back. Any resolution works, for example\n"
           "1366x768, 1920x1080, 2560x1440 and 3840x2160.\n\n"
        << format_options(specs) << "\nexamples:\n"
        << "  fractalis bench --size 1366x768 --json bench.json\n"
        << "  fractalis bench --scene mandelbulb --size 640x360 --lanes 16\n"
        << "  fractalis bench --explore --scene mandelbulb --size 1280x720\n"
        << "  fractalis bench --explore --error --frames 60 --size 640x360\n";
    return 0;
  }
  if (options.has("counts") && !options.has("explore"))
    throw UsageError("--counts: only with --explore (bench always reports the counts)");
  if (options.has("error") && !options.has("explore"))
    throw UsageError("--error: only with --explore");
  if (options.has("lattice") && !options.has("explore"))
    throw UsageError("--lattice: only with --explore");
  if (options.has("save-frame") && !options.has("error"))
    throw UsageError("--save-frame: only with --explore --error");
  if (options.has("explore")) {
    // Its figures go to the terminal only; a --json that would silently not be written is refused.
    if (options.has("json")) throw UsageError("--json: not written by bench --explore");
    return bench_explore(options, out, err);
  }
  BenchJob job = plan_bench(options);
  BenchReport report = run_bench(job, options);
  report_bench(job, report, out, err);
  return 0;
}

}  // namespace fr
