// `fractalis animate`: a scene along a camera path, to a video or a folder of numbered PNGs.
#include "animate/frame_plan.hpp"
#include "cli/commands.hpp"
#include "cli/prepared_scene.hpp"
#include "cli/progress.hpp"
#include "cli/watchdog.hpp"
#include "image/png_write.hpp"
#include "render/renderer.hpp"
#include "settings/settings.hpp"
#include "video/video_encoder.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <fstream>
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

}  // namespace

int command_animate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
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
  auto options = parse_options("animate", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis animate --path FILE --out OUT [--scene ID] [--fps N] [--size WxH]\n"
           "                         [--samples N] [options]\n\n"
           "Renders a scene along a camera path (see README: Camera paths). A path from its\n"
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
  const auto path_file = options.get("path");
  if (!path_file) throw UsageError("animate: --path FILE is required (a camera path)");
  const auto out_name = options.get("out");
  if (!out_name || out_name->empty()) throw UsageError("animate: --out OUT is required");
  const int fps =
      static_cast<int>(parse_integer("--fps", options.get("fps").value_or("24"), 1, 240));
  std::filesystem::path out_path(*out_name);
  while (out_path.has_parent_path() && !out_path.has_filename())  // "frames/" names "frames"
    out_path = out_path.parent_path();
  const VideoFormat* video = video_format_for(out_path);
  if (!video && is_other_media_extension(out_path.extension().string()))
    throw UsageError("--out " + out_path.string() + ": fractalis does not write '" +
                     out_path.extension().string() + "' (videos: " + video_extension_list() +
                     "; any other name is a folder of PNG frames)");
  if (video) {
    check_output_file("--out", out_path.string());
    if (options.has("force"))
      throw UsageError("--force: only a PNG folder resumes; a video is always written anew");
  }

  PreparedScene p = prepare_scene(options, kMaxImageSide);
  if (video && (p.render.width_px % 2 != 0 || p.render.height_px % 2 != 0))
    throw UsageError("--size " + std::to_string(p.render.width_px) + "x" +
                     std::to_string(p.render.height_px) + ": " + video->codec +
                     " video in yuv420p needs an even width and height");
  const SceneInfo& info = p.scene->info;
  const CameraPath path = load_path_option(info, *path_file);
  std::string problem;
  const auto plan = plan_frames(path.start_s(), path.end_s(), fps, &problem);
  if (!plan) throw UsageError("--fps " + std::to_string(fps) + ": " + problem);
  if (plan->ends_early)
    spdlog::info(
        "the path's {:.6g} s are not a whole number of frames at {} fps: the last frame "
        "shows {:.6g} s, before the closing keyframe",
        path.end_s() - path.start_s(), fps, plan->time_s(plan->frames - 1));
  check_memory(p.render, p.device, false);

  std::optional<SequenceState> sequence;
  std::unique_ptr<VideoEncoder> encoder;
  std::string error;
  if (video) {
    encoder = VideoEncoder::open(out_path, p.render.width_px, p.render.height_px, fps, &error);
    if (!encoder) throw std::runtime_error(error);
  } else {
    sequence = prepare_sequence_folder(out_path, identity_of(p, options, *path_file, fps), *plan,
                                       p.render.width_px, p.render.height_px, options.has("force"),
                                       &problem);
    if (!sequence) throw UsageError("--out: " + problem);
    if (sequence->done == plan->frames) {
      out << "all " << plan->frames << " frames of " << out_path.string()
          << " are there already (--force renders them anew)\n";
      return 0;
    }
    if (sequence->done > 0)
      out << "resuming: " << sequence->done << " of " << plan->frames << " frames are there\n";
  }

  ClRuntime runtime(p.device);
  Renderer renderer(runtime);
  Watchdog watchdog(p.render.watchdog_s, "rendering scene '" + info.id + "'");
  const auto start = std::chrono::steady_clock::now();
  const int already = sequence ? sequence->done : 0;
  Progress progress(err, "frame", plan->frames, already);
  int done = already;
  FrameImage image;  // reused: no allocation per frame
  size_t out_of_steps = 0, pixels = 0;
  for (int i = 0; i < plan->frames; ++i) {
    if (sequence && sequence->frame_done[i]) continue;
    const double t = plan->time_s(i);
    const PathSample sample = sample_camera_path(path, info, t);
    p.state.camera = sample.camera;
    p.state.params = sample.params;
    apply_scene_overrides(info, options, p.state);  // --param and the like hold for every frame
    p.state.time_s = t;
    update_scene(p, t);
    for (int sample = 0; sample < std::max(1, p.render.samples); ++sample)
      renderer.render_sample(info, p.state, p.render, sample, Readback::DisplayAndSteps);
    renderer.finish(p.render, Readback::DisplayAndSteps, image);
    watchdog.kick();
    const RayCounts rays = count_rays(image);
    out_of_steps += rays.out_of_steps;
    pixels += image.ray_status.size();
    const bool written = encoder ? encoder->add_frame(image.rgba8, &error)
                                 : write_png_atomic(out_path / frame_file_name(i), image.width_px,
                                                    image.height_px, image.rgba8, &error);
    if (!written) {
      throw std::runtime_error(error);
    }
    progress.update(++done);
  }
  if (encoder && !encoder->finish(&error)) {
    throw std::runtime_error(error);
  }
  watchdog.stop();
  progress.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int rendered = done - already;
  out << "rendered " << rendered << (rendered == 1 ? " frame of " : " frames of ") << info.id
      << " at " << p.render.width_px << "x" << p.render.height_px << ", " << fps << " fps on "
      << p.device.name << " in " << static_cast<int>(seconds + 0.5) << " s; wrote "
      << out_path.string();
  if (video)
    out << " (" << video->codec << ", " << plan->frames
        << (plan->frames == 1 ? " frame, " : " frames, ") << static_cast<double>(plan->frames) / fps
        << " s)";
  out << "\n";
  if (pixels > 0 && 100.0 * out_of_steps / pixels > kOutOfStepsWarnPercent)
    spdlog::warn("{:.2f}% of rays ran out of steps (render.max_steps = {}); raise render.max_steps",
                 100.0 * out_of_steps / pixels, p.render.max_steps);
  return 0;
}

}  // namespace fr
