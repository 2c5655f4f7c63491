// `fractalis animate`: a scene along a camera path, to a video or a folder of numbered PNGs.
#include "animate/frame_plan.hpp"
#include "cli/commands.hpp"
#include "cli/prepared_scene.hpp"
#include "cli/progress.hpp"
#include "cli/watchdog.hpp"
#include "image/png_write.hpp"
#include "mpi/mpi_world.hpp"
#include "mpi/shared_tasks.hpp"
#include "render/renderer.hpp"
#include "settings/settings.hpp"
#include "video/video_encoder.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace fr {
namespace {

// Extensions of video and image formats fractalis does not write: an `--out` ending in one is a
// mistake, not a folder name.
bool is_other_media_extension(std::string ext) {
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* e :
       {".avi", ".mov",  ".m4v", ".mpg", ".mpeg", ".ogv", ".ogg", ".flv",  ".wmv",  ".ts",
        ".gif", ".apng", ".png", ".jpg", ".jpeg", ".exr", ".tif", ".tiff", ".webp", ".y4m"})
    if (ext == e) return true;
  return false;
}

// What makes the frames of a PNG sequence what they are, for resuming (animate/frame_plan.hpp).
AnimationIdentity identity_of(const PreparedScene& p, const ParsedOptions& options,
                              const std::string& path_file, int fps) {
  std::ifstream in(path_file, std::ios::binary);
  std::stringstream path_bytes;
  path_bytes << in.rdbuf();
  std::string other;
  for (const auto& [name, values] : options.values) {
    if (name == "out" || name == "force" || name == "path" || name == "fps" || name == "size" ||
        name == "scene" || name == "config" || name == "plugins")
      continue;
    for (const auto& v : values) other += (other.empty() ? "--" : " --") + name + "=" + v;
  }
  return {
      {"scene", p.scene->info.id + " " + p.scene->info.version},
      {"path digest", digest_hex(path_bytes.str())},
      {"fps", std::to_string(fps)},
      {"size", std::to_string(p.render.width_px) + "x" + std::to_string(p.render.height_px)},
      {"settings digest", digest_hex(format_settings_toml(p.settings, ""))},
      {"options", other.empty() ? "(none)" : other},
  };
}

std::vector<OptionSpec> animate_option_specs() {
  auto specs = scene_option_specs();
  // The path gives each frame's time.
  specs.erase(std::remove_if(specs.begin(), specs.end(),
                             [](const OptionSpec& s) { return std::string(s.name) == "time"; }),
              specs.end());
  specs.push_back({"path", "FILE", false, "camera path (TOML keyframes), required"});
  specs.push_back({"fps", "N", false, "frames per second, 1 to 240 (default 24)"});
  specs.push_back({"out", "OUT", false,
                   "OUT.mp4 or OUT.mkv (H.264), OUT.webm (VP9), or a folder of numbered PNGs"});
  specs.push_back(
      {"force", nullptr, false, "render a PNG folder anew instead of resuming where it stopped"});
  specs.push_back({"help", nullptr, false, "show this help"});
  return specs;
}

// One animation, checked before anything is rendered: the scene, the path, the frames, where
// they go.
struct AnimateJob {
  PreparedScene p;
  std::string path_file;
  CameraPath path;
  std::optional<AnimationFrames> plan;
  int fps = 24;
  std::filesystem::path out_path;
  const VideoFormat* video = nullptr;  // null: a folder of PNG frames
  std::string raised;  // what render.auto_iterations last raised, said when it changes
};

AnimateJob plan_animation(const ParsedOptions& options) {
  AnimateJob job;
  const auto path_file = options.get("path");
  if (!path_file) throw UsageError("animate: --path FILE is required (a camera path)");
  job.path_file = *path_file;
  const auto out_name = options.get("out");
  if (!out_name || out_name->empty()) throw UsageError("animate: --out OUT is required");
  job.fps = static_cast<int>(parse_integer("--fps", options.get("fps").value_or("24"), 1, 240));
  job.out_path = *out_name;
  while (job.out_path.has_parent_path() && !job.out_path.has_filename())  // "frames/": "frames"
    job.out_path = job.out_path.parent_path();
  job.video = video_format_for(job.out_path);
  const std::string extension = job.out_path.extension().string();
  if (!job.video && is_other_media_extension(extension))
    throw UsageError("--out " + job.out_path.string() + ": fractalis does not write '" + extension +
                     "' (videos: " + video_extension_list() +
                     "; any other name is a folder of PNG frames)");
  if (job.video) {
    if (const std::string why = video_unavailable_reason(); !why.empty())
      throw UsageError("--out " + job.out_path.string() + ": " + why +
                       "; a name without a video extension is a folder of PNG frames");
    // Rank 0 writes a video: other ranks of an MPI job, perhaps on machines without that
    // folder, do not look for it.
    if (mpi_world().rank == 0) check_output_file("--out", job.out_path.string());
    if (options.has("force"))
      throw UsageError("--force: only a PNG folder resumes; a video is always written anew");
  }
  job.p = prepare_scene(options, kMaxImageSide);
  const RenderSettings& r = job.p.render;
  if (job.video && (r.width_px % 2 != 0 || r.height_px % 2 != 0))
    throw UsageError("--size " + std::to_string(r.width_px) + "x" + std::to_string(r.height_px) +
                     ": " + job.video->codec + " video in yuv420p needs an even width and height");
  job.path = load_path_option(job.p.scene->info, job.path_file);
  std::string problem;
  job.plan = plan_frames(job.path.start_s(), job.path.end_s(), job.fps, &problem);
  if (!job.plan) throw UsageError("--fps " + std::to_string(job.fps) + ": " + problem);
  if (job.plan->ends_early)
    spdlog::info(
        "the path's {:.6g} s are not a whole number of frames at {} fps: the last frame "
        "shows {:.6g} s, before the closing keyframe",
        job.path.end_s() - job.path.start_s(), job.fps, job.plan->time_s(job.plan->frames - 1));
  check_memory(r, job.p.device, false);
  return job;
}

// What the frames showed, for the report.
struct AnimateStats {
  int rendered = 0;
  size_t out_of_steps = 0, pixels = 0;
};

// Renders frame `i` of the animation into `image`: the path's view, parameters and time, then
// the scene's update. The frame's number is the scene's frame_index, so a frame is the same
// whichever process renders it, and in whatever order (a resumed folder, an MPI job).
void render_frame(AnimateJob& job, const ParsedOptions& options, RenderWorker& renderer, int i,
                  FrameImage& image) {
  PreparedScene& p = job.p;
  const SceneInfo& info = p.scene->info;
  const double t = job.plan->time_s(i);
  const PathSample sample = sample_camera_path(job.path, info, t);
  p.state.camera = sample.camera;
  p.state.camera_lo = sample.camera_lo;
  p.state.params = sample.params;
  apply_scene_overrides(info, options, p.state, p.preset);  // they hold for every frame
  p.state.time_s = t;
  p.state.frame_index = static_cast<uint64_t>(i);
  update_scene(p, t);
  for (int s = 0; s < std::max(1, p.render.samples); ++s)
    renderer.render_sample(info, p.state, p.render, s, Readback::DisplayAndSteps);
  renderer.finish(p.render, Readback::DisplayAndSteps, image);
  // A zoom's counts rise as it deepens: each change said once, with its frame.
  const std::string raised = describe_raised(renderer.raised_iterations());
  if (raised != job.raised) {
    if (!raised.empty())
      spdlog::info("frame {}: for the view's depth (render.auto_iterations): {}", i, raised);
    job.raised = raised;
  }
}

void write_frame_png(const AnimateJob& job, int i, const FrameImage& image) {
  std::string error;
  if (!write_png_atomic(job.out_path / frame_file_name(i), image.width_px, image.height_px,
                        image.rgba8, &error))
    throw std::runtime_error(error);
}

// Renders the frames not there yet, each into the encoder or its PNG, under the watchdog.
AnimateStats render_frames(AnimateJob& job, const ParsedOptions& options, VideoEncoder* encoder,
                           const SequenceState* sequence, std::ostream& err) {
  RenderWorker& renderer = *job.p.worker;
  Watchdog watchdog(job.p.render.watchdog_s, "rendering scene '" + job.p.scene->info.id + "'");
  const int already = sequence ? sequence->done : 0;
  Progress progress(err, "frame", job.plan->frames, already);
  AnimateStats stats;
  FrameImage image;  // reused: no allocation per frame
  std::string error;
  for (int i = 0; i < job.plan->frames; ++i) {
    if (sequence && sequence->frame_done[i]) continue;
    render_frame(job, options, renderer, i, image);
    watchdog.kick();
    const RayCounts rays = count_rays(image);
    stats.out_of_steps += rays.out_of_steps;
    stats.pixels += image.ray_status.size();
    if (encoder) {
      if (!encoder->add_frame(image.rgba8, &error)) throw std::runtime_error(error);
    } else {
      write_frame_png(job, i, image);
    }
    ++stats.rendered;
    progress.update(already + stats.rendered);
  }
  if (encoder && !encoder->finish(&error)) throw std::runtime_error(error);
  watchdog.stop();
  progress.finish();
  return stats;
}

// An MPI job's ranks other than 0 (mpi/shared_tasks.hpp): render the frames rank 0 hands out and
// send back the counts of their rays and, for a video, the pixels; a PNG frame is written here,
// where it was rendered.
void serve_frames(AnimateJob& job, const ParsedOptions& options) {
  FrameImage image;
  const int rank = mpi_world().rank;
  serve_tasks([&](int i) {
    // Each frame under its own watchdog: waiting for rank 0 between frames is not rendering.
    Watchdog watchdog(job.p.render.watchdog_s, "rendering scene '" + job.p.scene->info.id +
                                                   "' (rank " + std::to_string(rank) + ", frame " +
                                                   std::to_string(i) + ")");
    render_frame(job, options, *job.p.worker, i, image);
    const uint64_t counts[2] = {count_rays(image).out_of_steps, image.ray_status.size()};
    const size_t pixel_bytes = job.video ? image.rgba8.size() : 0;
    std::vector<uint8_t> bytes(sizeof counts + pixel_bytes);
    std::memcpy(bytes.data(), counts, sizeof counts);
    if (job.video)
      std::memcpy(bytes.data() + sizeof counts, image.rgba8.data(), pixel_bytes);
    else
      write_frame_png(job, i, image);
    return bytes;
  });
}

// Rank 0 of an MPI job: hands the frames not there yet to the other ranks and encodes a video's
// frames in order as they come back.
AnimateStats lead_frames(const AnimateJob& job, VideoEncoder* encoder,
                         const SequenceState* sequence, std::ostream& err) {
  std::vector<int> frames;
  for (int i = 0; i < job.plan->frames; ++i)
    if (!sequence || !sequence->frame_done[i]) frames.push_back(i);
  const int already = sequence ? sequence->done : 0;
  Progress progress(err, "frame", job.plan->frames, already);
  AnimateStats stats;
  TaskSharing how;
  how.noun = "frame";
  // A video's frames wait at rank 0 for the ones before them: two per rank at most. PNG frames
  // are written where they are rendered; only their counts come back.
  how.window = encoder ? 2 * static_cast<size_t>(mpi_world().size) : 0;
  how.deadline_s = rank_task_deadline_s(job.p.render.watchdog_s);
  const size_t frame_bytes =
      4 * static_cast<size_t>(job.p.render.width_px) * static_cast<size_t>(job.p.render.height_px);
  std::vector<uint8_t> rgba8;
  std::string error;
  lead_tasks(frames, how, [&](int i, std::vector<uint8_t>& bytes) {
    uint64_t counts[2] = {};
    const size_t expected = sizeof counts + (encoder ? frame_bytes : 0);
    if (bytes.size() != expected)
      throw std::runtime_error("frame " + std::to_string(i) + " came back with " +
                               std::to_string(bytes.size()) + " bytes, not " +
                               std::to_string(expected));
    std::memcpy(counts, bytes.data(), sizeof counts);
    stats.out_of_steps += counts[0];
    stats.pixels += counts[1];
    if (encoder) {
      rgba8.assign(bytes.begin() + sizeof counts, bytes.end());
      if (!encoder->add_frame(rgba8, &error)) throw std::runtime_error(error);
    }
    ++stats.rendered;
    progress.update(already + stats.rendered);
  });
  if (encoder && !encoder->finish(&error)) throw std::runtime_error(error);
  progress.finish();
  return stats;
}

void report_animation(const AnimateJob& job, const AnimateStats& stats, double seconds,
                      std::ostream& out) {
  const RenderSettings& r = job.p.render;
  out << "rendered " << stats.rendered << (stats.rendered == 1 ? " frame of " : " frames of ")
      << job.p.scene->info.id << " at " << r.width_px << "x" << r.height_px << ", " << job.fps
      << " fps on " << job.p.device.name;
  if (mpi_world().shared()) out << " by " << rendering_ranks_text();
  out << " in " << static_cast<int>(seconds + 0.5) << " s; wrote " << job.out_path.string();
  if (job.video)
    out << " (" << job.video->codec << ", " << job.plan->frames
        << (job.plan->frames == 1 ? " frame, " : " frames, ")
        << static_cast<double>(job.plan->frames) / job.fps << " s)";
  out << "\n";
  if (stats.pixels > 0 && 100.0 * stats.out_of_steps / stats.pixels > kOutOfStepsWarnPercent)
    spdlog::warn("{:.2f}% of rays ran out of steps (render.max_steps = {}); raise render.max_steps",
                 100.0 * stats.out_of_steps / stats.pixels, r.max_steps);
}

// Where the frames go: a video's encoder, or a PNG folder and which of its frames are there.
struct AnimationOutput {
  std::unique_ptr<VideoEncoder> encoder;
  std::optional<SequenceState> sequence;
};

// Opens the video, or readies the PNG folder (rank 0's job in an MPI job: when it fails, the
// other ranks are dismissed with its exit status).
AnimationOutput open_animation_output(const AnimateJob& job, const ParsedOptions& options) {
  const RenderSettings& r = job.p.render;
  AnimationOutput output;
  try {
    if (job.video) {
      std::string error;
      output.encoder = VideoEncoder::open(job.out_path, r.width_px, r.height_px, job.fps, &error);
      if (!output.encoder) throw std::runtime_error(error);
    } else {
      std::string problem;
      output.sequence = prepare_sequence_folder(
          job.out_path, identity_of(job.p, options, job.path_file, job.fps), *job.plan, r.width_px,
          r.height_px, options.has("force"), &problem);
      if (!output.sequence) throw UsageError("--out: " + problem);
    }
  } catch (...) {
    if (mpi_world().shared()) dismiss_ranks(exit_status_of(std::current_exception()));
    throw;
  }
  return output;
}

}  // namespace

int command_animate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const auto specs = animate_option_specs();
  auto options = parse_options("animate", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis animate --path FILE --out OUT [--scene ID] [--fps N] [--size WxH]\n"
           "                         [--samples N] [options]\n\n"
           "Renders a scene along a camera path (see docs/rendering.md). A path from its\n"
           "first keyframe to its last, D seconds, at N fps has floor(D x N) + 1 frames: the\n"
           "first and the closing keyframe both included; a video shows each for 1/N s.\n"
           "A video (.mp4, .mkv: H.264; .webm: VP9; yuv420p, so even sizes) is written whole or\n"
           "not at all. Any other OUT is a folder of frame_000000.png ...; an interrupted run\n"
           "resumes where it stopped, if nothing that changes the frames changed.\n\n"
        << format_options(specs) << "\nexamples:\n"
        << "  fractalis animate --scene mandelbulb --path flight.toml --fps 30 --size 1280x720 "
           "--out flight.mp4\n"
        << "  fractalis animate --scene menger --path orbit.toml --fps 24 --out frames/\n";
    return 0;
  }
  // Every rank of an MPI job plans the animation; any that fails ends them all.
  AnimateJob job = prepare_on_every_rank([&] { return plan_animation(options); });
  const MpiWorld& world = mpi_world();
  if (world.rank != 0) {
    serve_frames(job, options);
    return 0;
  }
  AnimationOutput output = open_animation_output(job, options);
  std::optional<SequenceState>& sequence = output.sequence;
  VideoEncoder* encoder = output.encoder.get();
  if (sequence && sequence->done == job.plan->frames) {
    if (world.shared()) dismiss_ranks(0);
    out << "all " << job.plan->frames << " frames of " << job.out_path.string()
        << " are there already (--force renders them anew)\n";
    return 0;
  }
  if (sequence && sequence->done > 0)
    out << "resuming: " << sequence->done << " of " << job.plan->frames << " frames are there\n";
  const auto start = std::chrono::steady_clock::now();
  const AnimateStats stats =
      world.shared() ? lead_frames(job, encoder, sequence ? &*sequence : nullptr, err)
                     : render_frames(job, options, encoder, sequence ? &*sequence : nullptr, err);
  report_animation(job, stats,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                   out);
  return 0;
}

}  // namespace fr
