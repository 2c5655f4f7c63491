#include "bench/frame_stats.hpp"
#include "cli/commands.hpp"
#include "cli/prepared_scene.hpp"
#include "cli/progress.hpp"
#include "io/atomic_file.hpp"
#include "io/cache_dirs.hpp"
#include "platform/files.hpp"
#include "platform/interrupt.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_reference.hpp"
#include "sweep/sweep_report.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace fr {
namespace {

std::filesystem::path default_cache_dir() {
  const auto base = fractalis_cache_dir();
  return base.empty() ? std::filesystem::temp_directory_path() / "fractalis-sweep-cache"
                      : base / "sweep";
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

// The output folder exists (made if need be) and is writable, or a UsageError says why.
void check_out_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw UsageError("--out: '" + dir.string() + "' is not a folder");
  std::filesystem::create_directories(dir, ec);
  if (ec) throw UsageError("--out: cannot create '" + dir.string() + "': " + ec.message());
  if (!can_write_in(dir)) throw UsageError("--out: folder '" + dir.string() + "' is not writable");
}

std::string config_name(const SweepConfig& c) {
  return c.knob == "default" ? "default" : c.knob + "=" + c.value;
}

// --knobs' help, from the sweep plan's knob list, so help never lags behind it.
const std::string& knobs_help() {
  static const std::string text = [] {
    std::string t = "comma-separated knobs to sweep (default: all that apply):";
    size_t column = t.size();
    for (const auto& k : all_knob_names()) {
      if (column + k.size() > 60) {
        t += "\n                                ";
        column = 0;
      }
      t += (column == 0 || &k == &all_knob_names().front() ? " " : ", ") + k;
      column += k.size() + 2;
    }
    return t;
  }();
  return text;
}

std::vector<OptionSpec> sweep_option_specs() {
  auto specs = scene_option_specs();
  specs.push_back({"out", "DIR", false,
                   "folder for sweep.csv, sweep.json, sweep.svg "
                   "(default sweep-SCENE)"});
  specs.push_back({"knobs", "LIST", false, knobs_help().c_str()});
  specs.push_back({"frames", "N", false,
                   "timing rounds: frames timed per configuration, interleaved (default 9)"});
  specs.push_back({"reference-samples", "N", false,
                   "samples of a path-traced reference (default 1024; with --integrator path)"});
  specs.push_back({"cache", "DIR", false,
                   "reference cache (default: sweep/ in fractalis's cache folder,\n"
                   "                                 see `fractalis cache`)"});
  specs.push_back({"help", nullptr, false, "show this help"});
  return specs;
}

// What one sweep does, from its options: the scene, the configurations, where the results go.
struct SweepJob {
  PreparedScene p;
  std::vector<SweepConfig> configs;
  int frames = 9;
  int path_reference_samples = kPathReferenceSamples;
  std::filesystem::path out_dir;
  std::filesystem::path cache_dir;
};

SweepJob plan_job(ParsedOptions& options) {
  if (!options.has("size")) options.values["size"] = {"320x180"};
  SweepJob job;
  job.frames =
      static_cast<int>(parse_integer("--frames", options.get("frames").value_or("9"), 1, 1000));
  job.path_reference_samples = static_cast<int>(parse_integer(
      "--reference-samples",
      options.get("reference-samples").value_or(std::to_string(kPathReferenceSamples)), 1, 65536));
  job.cache_dir = options.get("cache").value_or(default_cache_dir().string());
  job.p = prepare_scene(options);
  job.out_dir = options.get("out").value_or("sweep-" + job.p.scene->info.id);
  if (job.out_dir.empty()) throw UsageError("--out: empty folder name");
  check_memory(job.p.render, job.p.device, true);
  std::vector<std::string> knobs = knob_names(job.p.scene->info, job.p.render);
  if (auto list = options.get("knobs")) {
    knobs = split_list(*list);
    if (knobs.empty()) throw UsageError("--knobs: empty sweep (name at least one knob)");
  }
  try {
    job.configs = plan_sweep(job.p.scene->info, job.p.render, knobs);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--knobs: ") + e.what());
  }
  check_out_dir(job.out_dir);
  return job;
}

// Every configuration's picture and geometry against the reference (this also builds its
// kernel and warms it up). Returns the share of pixels where lane widths 1 and 16 differ, or -1
// when the lanes knob was not swept.
double measure_configs(const SweepJob& job, RenderWorker& renderer, SweepResult& result,
                       Progress& progress) {
  const PreparedScene& p = job.p;
  const double pixel_angle =
      make_camera_rays(p.state.camera, p.render.width_px, p.render.height_px).pixel_angle_rad;
  std::vector<uint8_t> lanes_image[2];
  for (size_t i = 0; i < job.configs.size() && !InterruptCatcher::interrupted(); ++i) {
    const SweepConfig& c = job.configs[i];
    progress.update(static_cast<int>(i) + 1, "measuring " + config_name(c));
    renderer.prepare(p.scene->info, p.state, c.settings);
    // The picture with the configuration's samples, and the geometry from centred rays like the
    // reference's (a jittered last sample would count as depth error).
    FrameImage image = renderer.render(p.scene->info, p.state, c.settings, true);
    RenderSettings centred = c.settings;
    centred.samples = 1;
    const FrameImage geometry = renderer.render(p.scene->info, p.state, centred, true);
    image.depth = geometry.depth;
    image.normal = geometry.normal;
    image.ray_status = geometry.ray_status;
    result.rows.push_back({c.knob, c.value, 0,
                           compare_to_reference(image, result.reference.image, pixel_angle),
                           false});
    if (c.knob == "lanes") lanes_image[c.value == "1" ? 0 : 1] = image.rgba8;
  }
  if (lanes_image[0].empty() || lanes_image[1].empty()) return -1;
  size_t differing = 0;
  for (size_t i = 0; i + 3 < lanes_image[0].size(); i += 4)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(lanes_image[0][i + c]) - int(lanes_image[1][i + c])) > 2) {
        ++differing;
        break;
      }
  return double(differing) / double(lanes_image[0].size() / 4);
}

// The timing, in rounds that render each configuration once, so that the machine's slow moments
// spread over all of them instead of landing on a few; each row gets its median.
void time_configs(const SweepJob& job, RenderWorker& renderer, SweepResult& result,
                  Progress& progress) {
  using clock = std::chrono::steady_clock;
  const auto now_ms = [] {
    return std::chrono::duration<double, std::milli>(clock::now().time_since_epoch()).count();
  };
  const PreparedScene& p = job.p;
  std::vector<std::vector<double>> times(job.configs.size());
  for (int round = 0; round < job.frames && !InterruptCatcher::interrupted(); ++round) {
    progress.update(
        static_cast<int>(job.configs.size()) + 1,
        "timing, round " + std::to_string(round + 1) + " of " + std::to_string(job.frames));
    for (size_t i = 0; i < job.configs.size() && !InterruptCatcher::interrupted(); ++i) {
      const auto t = time_frames(
          1, [&](int) { renderer.render(p.scene->info, p.state, job.configs[i].settings); },
          now_ms);
      times[i].push_back(t[0]);
    }
  }
  for (size_t i = 0; i < result.rows.size() && !times[i].empty(); ++i)
    result.rows[i].frame_ms = summarize_frames(times[i]).p50_ms;
}

// The table on `out`, then sweep.csv, sweep.json and sweep.svg, each written atomically.
void report_sweep(const SweepJob& job, const SweepResult& result, std::ostream& out) {
  char line[640];
  std::snprintf(line, sizeof line,
                "sweep of %s at %dx%d on %s, %d timed frames per configuration\n"
                "reference: double, plain sphere tracing, %d samples, k = %g after %d renders%s; "
                "its last refinement changed the picture by %.3f (8-bit MAE) and the surface by "
                "%.3f footprints\n",
                result.scene_id.c_str(), result.width_px, result.height_px,
                job.p.device.name.c_str(), job.frames, result.reference.samples,
                result.reference.hit_threshold_k, result.reference.refinements,
                result.reference.from_cache ? " (cached)" : "", result.reference.convergence_mae,
                result.reference.convergence_depth_px);
  out << line << format_sweep_table(result);
  for (const auto& note : result.notes) out << "note: " << note << "\n";
  std::string error;
  for (const auto& [file, text] :
       {std::pair<const char*, std::string>{"sweep.csv", format_sweep_csv(result)},
        {"sweep.json", format_sweep_json(result)},
        {"sweep.svg", format_sweep_svg(result)}})
    if (!write_file_atomic(job.out_dir / file, text, &error)) throw std::runtime_error(error);
  out << "wrote " << (job.out_dir / "sweep.csv").string() << ", sweep.json, sweep.svg\n";
}

}  // namespace

int command_sweep(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  // Ctrl-C and SIGTERM stop the sweep between two renders; the results are written only at the
  // end, atomically, so an interrupted sweep leaves no file behind (a reference already cached
  // stays: it is complete).
  InterruptCatcher interrupt_catcher;  // from the start: a Ctrl-C while loading plugins counts too
  const auto specs = sweep_option_specs();
  auto options = parse_options("sweep", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis sweep [--scene ID] [--size WxH] [--out DIR] [--knobs LIST] "
           "[options]\n\n"
           "Measures image and geometric error against frame time: renders the view under each\n"
           "quality knob's values (one at a time, the rest at their defaults), compares every\n"
           "frame with a converged double-precision reference of the same view, and writes a\n"
           "table (CSV, JSON) and a plot (SVG) of error against time with the Pareto front.\n\n"
        << format_options(specs) << "\nexample:\n"
        << "  fractalis sweep --scene menger --size 320x180 --out sweep-menger\n";
    return 0;
  }
  SweepJob job = plan_job(options);
  PreparedScene& p = job.p;
  update_scene(p, p.state.time_s);
  // No time limit on a sample: the reference's may legitimately take long (Ctrl-C ends a sweep).
  RenderWorker renderer(p.device, command_worker_limits(p.settings.plugins, 0));
  renderer.name_scene_file(p.scene->info.id, p.scene->file);
  SweepResult result;
  result.scene_id = p.scene->info.id;
  result.device = p.device.name;
  result.width_px = p.render.width_px;
  result.height_px = p.render.height_px;
  result.timed_frames = job.frames;
  // Steps: the reference, each configuration's measurement, the timing rounds.
  Progress progress(err, "step", static_cast<int>(job.configs.size()) + 2);
  std::string warning;
  result.reference = make_reference(
      renderer, p.scene->info, p.state, p.render, p.device.name, job.cache_dir,
      [&](double k, int level) {
        progress.update(
            0, "reference: refinement " + std::to_string(level + 1) + ", k = " + std::to_string(k));
        return !InterruptCatcher::interrupted();
      },
      &warning, job.path_reference_samples);
  if (!warning.empty()) {
    progress.finish();  // off the progress bar's line
    spdlog::warn("{}", warning);
  }
  const double lanes_difference = measure_configs(job, renderer, result, progress);
  time_configs(job, renderer, result, progress);
  if (!InterruptCatcher::interrupted()) progress.update(static_cast<int>(job.configs.size()) + 2);
  progress.finish();
  if (InterruptCatcher::interrupted()) {
    spdlog::warn("sweep interrupted; nothing written");
    return 130;
  }
  analyse_sweep(result, lanes_difference);
  // A view of empty space measures nothing about the surface: say so rather than print zeros.
  const auto& ref_depth = result.reference.image.depth;
  if (std::none_of(ref_depth.begin(), ref_depth.end(), [](float d) { return std::isfinite(d); }))
    result.notes.push_back(
        "the reference shows no surface in this view: the geometric errors are empty");
  report_sweep(job, result, out);
  return 0;
}

}  // namespace fr
