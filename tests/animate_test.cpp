// `fractalis animate`: videos that ffprobe reads as asked (frames, size, duration, codec), frames
// that show the path at their time (checked against `render --path --time`, an independent
// code path through the CLI), PNG sequences that resume and refuse to mix animations, and bad
// input refused with exit code 2 before rendering.
#include "cli/cli.hpp"
#include "cli_run.hpp"
#include "path/camera_path.hpp"
#include "test_support.hpp"
#include "video/video_encoder.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

namespace fr {
namespace {

using test::CliRun;
using test::expect_usage_error;
using test::run;

// A shell command's standard output.
std::string capture(const std::string& command) {
  std::string text;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return text;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) text.append(buffer, n);
  pclose(pipe);
  return text;
}

// ffprobe's "key=value" lines for the video's first stream and its container.
std::map<std::string, std::string> probe(const std::filesystem::path& video) {
  const std::string text = capture(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,pix_fmt,nb_read_frames:format=duration -of default=nw=1 '" +
      video.string() + "'");
  std::map<std::string, std::string> fields;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
    if (auto eq = line.find('='); eq != std::string::npos)
      fields[line.substr(0, eq)] = line.substr(eq + 1);
  return fields;
}

// A path around the Mandelbulb: 1 s, three keyframes, the power changing on the way.
std::filesystem::path write_path(const std::filesystem::path& dir) {
  const auto file = dir / "orbit.toml";
  std::ofstream(file) << "[[keyframe]]\ntime_s = 0\neye = [0, 0.4, 2.8]\ntarget = [0, 0, 0]\n"
                         "[[keyframe]]\ntime_s = 0.5\neye = [2.8, 0.2, 0]\ntarget = [0, 0, 0]\n"
                         "[keyframe.params]\npower = 6\n"
                         "[[keyframe]]\ntime_s = 1\neye = [0, -0.3, -2.8]\ntarget = [0, 0, 0]\n";
  return file;
}

const std::vector<std::string> kCommon = {"animate", "--scene", "mandelbulb", "--size",
                                          "96x64",   "--fps",   "8"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Mean absolute difference of the colour channels, in 1/255.
double mean_difference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  if (a.size() != b.size() || a.empty()) return 1e9;
  double sum = 0;
  size_t n = 0;
  for (size_t p = 0; p + 3 < a.size(); p += 4)
    for (int c = 0; c < 3; ++c, ++n) sum += std::abs(int(a[p + c]) - int(b[p + c]));
  return sum / double(n);
}

// The still `render --path FILE --time T` makes, as RGBA8.
std::vector<uint8_t> still_at(const std::filesystem::path& path, double time_s,
                              const std::filesystem::path& png) {
  std::ostringstream t;
  t.precision(17);
  t << time_s;
  const CliRun r = run({"render", "--scene", "mandelbulb", "--size", "96x64", "--path",
                        path.string(), "--time", t.str(), "--out", png.string()});
  EXPECT_EQ(r.code, 0) << r.err;
  return test::load_png(png).rgba8;
}

// 1 s at 8 fps: 9 frames (both ends), 9/8 s of video, as ffprobe counts them, in each container.
TEST(Animate, VideoHasTheFramesSizeAndDurationAsked) {
  if (!video_unavailable_reason().empty()) GTEST_SKIP() << video_unavailable_reason();
  ASSERT_FALSE(capture("command -v ffprobe").empty()) << "ffprobe (Debian's ffmpeg) is needed";
  const auto dir = test::fresh_dir("animate_video");
  const auto path = write_path(dir);
  for (const auto& [name, codec] : std::vector<std::pair<std::string, std::string>>{
           {"orbit.mp4", "h264"}, {"orbit.mkv", "h264"}, {"orbit.webm", "vp9"}}) {
    const auto video = dir / name;
    const CliRun r = run(with(kCommon, {"--path", path.string(), "--out", video.string()}));
    ASSERT_EQ(r.code, 0) << name << ": " << r.err;
    auto fields = probe(video);
    EXPECT_EQ(fields["codec_name"], codec) << name;
    EXPECT_EQ(fields["width"], "96") << name;
    EXPECT_EQ(fields["height"], "64") << name;
    EXPECT_EQ(fields["pix_fmt"], "yuv420p") << name;
    EXPECT_EQ(fields["nb_read_frames"], "9") << name;
    ASSERT_FALSE(fields["duration"].empty()) << name;
    EXPECT_NEAR(std::stod(fields["duration"]), 9.0 / 8.0, 0.002) << name;
    // Only the video: no temporary file left beside it.
    for (const auto& e : std::filesystem::directory_iterator(dir))
      EXPECT_EQ(e.path().filename().string().rfind(".", 0), std::string::npos) << e.path();
  }
}

// Decoded frame i shows the path at i / fps: closer to the still at its own time than to its
// neighbours' (the encoding is lossy, so the check is by distance, not equality).
TEST(Animate, VideoFrameShowsThePathAtItsTime) {
  if (!video_unavailable_reason().empty()) GTEST_SKIP() << video_unavailable_reason();
  const auto dir = test::fresh_dir("animate_frames");
  const auto path = write_path(dir);
  const auto video = dir / "orbit.mkv";
  ASSERT_EQ(run(with(kCommon, {"--path", path.string(), "--out", video.string()})).code, 0);
  const auto raw = dir / "frames.rgba";
  capture("ffmpeg -v error -y -i '" + video.string() + "' -f rawvideo -pix_fmt rgba '" +
          raw.string() + "'");
  const std::string bytes = test::read_file(raw);
  const size_t frame_bytes = 96 * 64 * 4;
  ASSERT_EQ(bytes.size(), 9 * frame_bytes);
  for (const int i : {0, 3, 8}) {
    const std::vector<uint8_t> decoded(bytes.begin() + i * frame_bytes,
                                       bytes.begin() + (i + 1) * frame_bytes);
    const double own = mean_difference(decoded, still_at(path, i / 8.0, dir / "own.png"));
    // yuv420p halves the chroma of a detailed fractal: a few levels of 255 on average.
    EXPECT_LT(own, 7.0) << "frame " << i << " against render --time " << i / 8.0;
    const int other = i == 8 ? 7 : i + 1;
    const double neighbour =
        mean_difference(decoded, still_at(path, other / 8.0, dir / "other.png"));
    EXPECT_LT(own * 2, neighbour) << "frame " << i << " against the still at frame " << other;
  }
}

// A PNG sequence: frame i is exactly the still at i / fps; an interrupted sequence (frames
// missing, one cut short) resumes with only those frames; a changed option refuses to mix.
TEST(Animate, PngSequenceResumesAndRefusesToMix) {
  const auto dir = test::fresh_dir("animate_png");
  const auto path = write_path(dir);
  const auto frames = dir / "frames";
  const auto args = with(kCommon, {"--path", path.string(), "--out", frames.string()});
  CliRun r = run(args);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const int i : {0, 5, 8}) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", i);
    EXPECT_EQ(test::load_png(frames / name).rgba8, still_at(path, i / 8.0, dir / "still.png"))
        << name;
  }
  EXPECT_FALSE(std::filesystem::exists(frames / "frame_000009.png"));
  const std::string frame4 = test::read_file(frames / "frame_000004.png");

  // "Interrupted": two frames missing, one cut short.
  std::filesystem::remove(frames / "frame_000002.png");
  std::filesystem::remove(frames / "frame_000007.png");
  std::filesystem::resize_file(frames / "frame_000004.png", 100);
  r = run(args);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("resuming: 6 of 9 frames are there"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rendered 3 frames"), std::string::npos) << r.out;
  EXPECT_EQ(test::read_file(frames / "frame_000004.png"), frame4);
  EXPECT_TRUE(std::filesystem::exists(frames / "frame_000002.png"));

  r = run(args);
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("all 9 frames"), std::string::npos) << r.out;

  // Another power is another animation: refused, then redone with --force.
  r = run(with(args, {"--param", "power=5"}));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("holds frames of another animation (its options was (none), now "
                       "--param=power=5); --force renders it anew"),
            std::string::npos)
      << r.err;
  r = run({"animate", "--scene", "mandelbulb", "--size", "96x64", "--fps", "4", "--path",
           path.string(), "--out", frames.string(), "--param", "power=5", "--force"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rendered 5 frames"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(frames / "frame_000005.png"))
      << "--force removes the old sequence's frames";
}

// Most cases name a video: they check what is checked before rendering one.
TEST(Animate, BadInputIsRefusedBeforeRendering) {
  if (!video_unavailable_reason().empty()) GTEST_SKIP() << video_unavailable_reason();
  const auto dir = test::fresh_dir("animate_bad");
  const auto path = write_path(dir);
  const std::string p = path.string();
  auto out = [&](const char* name) { return (dir / name).string(); };
  expect_usage_error(with(kCommon, {"--path", p, "--out", out("a.avi")}),
                     "fractalis does not write '.avi' (videos: '.mp4', '.mkv', '.webm'");
  expect_usage_error(with(kCommon, {"--out", out("a.mp4")}), "--path FILE is required");
  expect_usage_error(with(kCommon, {"--path", p}), "--out OUT is required");
  expect_usage_error({"animate", "--path", p, "--fps", "0", "--out", out("a.mp4")},
                     "--fps: 0 is outside [1, 240]");
  expect_usage_error({"animate", "--path", p, "--size", "97x64", "--out", out("a.mp4")},
                     "--size 97x64: H.264 video in yuv420p needs an even width and height");
  expect_usage_error({"animate", "--path", p, "--size", "16386x64", "--out", out("a.mp4")},
                     "outside [1, 16384]");
  expect_usage_error(with(kCommon, {"--path", p, "--force", "--out", out("a.webm")}),
                     "--force: only a PNG folder resumes");
  expect_usage_error(with(kCommon, {"--path", p, "--time", "1", "--out", out("a.mp4")}),
                     "unknown option '--time'");
  expect_usage_error(with(kCommon, {"--path", p, "--out", "/no/such/folder/a.mp4"}),
                     "folder '/no/such/folder' does not exist");
  std::ofstream(dir / "one.toml")
      << "[[keyframe]]\ntime_s = 0\neye = [0, 0, 3]\ntarget = [0, 0, 0]\n";
  expect_usage_error(with(kCommon, {"--path", out("one.toml"), "--out", out("a.mp4")}),
                     "one.toml:1: a path needs at least two keyframes");
  std::ofstream(dir / "order.toml")
      << "[[keyframe]]\ntime_s = 1\neye = [0, 0, 3]\ntarget = [0, 0, 0]\n"
         "[[keyframe]]\ntime_s = 0.5\neye = [0, 0, 2]\ntarget = [0, 0, 0]\n";
  expect_usage_error(with(kCommon, {"--path", out("order.toml"), "--out", out("a.mp4")}),
                     "order.toml:6: keyframe 2: time_s 0.5 is not after the previous keyframe's 1");
  std::ofstream(dir / "param.toml")
      << "[[keyframe]]\ntime_s = 0\neye = [0, 0, 3]\ntarget = [0, 0, 0]\n"
         "[keyframe.params]\npowr = 3\n"
         "[[keyframe]]\ntime_s = 1\neye = [0, 0, 2]\ntarget = [0, 0, 0]\n";
  expect_usage_error(with(kCommon, {"--path", out("param.toml"), "--out", out("a.mp4")}),
                     "param.toml:6: keyframe 1: scene 'mandelbulb' has no parameter 'powr'");
  std::ofstream(dir / "long.toml")
      << "[[keyframe]]\ntime_s = 0\neye = [0, 0, 3]\ntarget = [0, 0, 0]\n"
         "[[keyframe]]\ntime_s = 1e6\neye = [0, 0, 2]\ntarget = [0, 0, 0]\n";
  expect_usage_error(with(kCommon, {"--path", out("long.toml"), "--out", out("a.mp4")}),
                     "more than 1000000 frames");
  std::filesystem::create_directory(dir / "mine");
  std::ofstream(dir / "mine" / "frame_000000.png") << "not ours";
  expect_usage_error(with(kCommon, {"--path", p, "--out", out("mine")}),
                     "holds frames that fractalis did not record; --force replaces them");
  std::ofstream(dir / "plain") << "a file";
  expect_usage_error(with(kCommon, {"--path", p, "--out", out("plain")}), "is not a folder");
  // Nothing was written by any of them.
  EXPECT_FALSE(std::filesystem::exists(dir / "a.mp4"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a.webm"));
}

// A build without video (the Windows build) refuses each video name at once, saying why and what
// it writes instead, and leaves nothing behind.
TEST(Animate, ABuildWithoutVideoRefusesVideosBeforeRendering) {
  if (video_unavailable_reason().empty()) GTEST_SKIP() << "this build writes videos";
  const auto dir = test::fresh_dir("animate_no_video");
  const std::string p = write_path(dir).string();
  for (const char* name : {"a.mp4", "a.mkv", "a.webm", "A.MP4"}) {
    expect_usage_error(with(kCommon, {"--path", p, "--out", (dir / name).string()}),
                       "no video encoder (it was built without FFmpeg); a name without a video "
                       "extension is a folder of PNG frames");
    EXPECT_FALSE(std::filesystem::exists(dir / name)) << name;
  }
}

}  // namespace
}  // namespace fr

namespace fr {
namespace {

// The benchmark scene's route is the ordinary path file config/paths/benchmark.toml, flown by
// `bench`: a lap at radius 7.4 bobbing 1.8 + 0.6 sin(2a) (the formula the scene's update callback
// used), which the spline through its 17 keyframes follows closely.
TEST(Animate, BenchmarkRouteIsAnOrdinaryPath) {
  auto scene =
      test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "benchmark" PLUGIN_SUFFIX);
  ASSERT_TRUE(scene);
  std::vector<PathProblem> problems;
  const auto path =
      load_camera_path(std::filesystem::path(SOURCE_DIR) / "config" / "paths" / "benchmark.toml",
                       scene->info, &problems);
  ASSERT_TRUE(path) << problems.front().to_string();
  EXPECT_EQ(path->start_s(), 0.0);
  EXPECT_EQ(path->end_s(), 20.0);
  double worst_radius = 0, worst_height = 0, worst_aim_deg = 0;
  for (int i = 0; i <= 400; ++i) {
    const PathSample s = sample_camera_path(*path, scene->info, 20.0 * i / 400);
    const double radius = std::hypot(s.camera.eye[0], s.camera.eye[2]);
    const double a = std::atan2(s.camera.eye[0], s.camera.eye[2]);
    worst_radius = std::max(worst_radius, std::abs(radius / 7.4 - 1));
    worst_height =
        std::max(worst_height, std::abs(s.camera.eye[1] - (1.8 + 0.6 * std::sin(2 * a))));
    // Orientation is interpolated (slerp), not re-aimed: the view stays near the centre.
    const glm::dvec3 eye(s.camera.eye[0], s.camera.eye[1], s.camera.eye[2]);
    const glm::dvec3 view(s.camera.target[0], s.camera.target[1], s.camera.target[2]);
    const double cos_aim =
        glm::dot(glm::normalize(view - eye), glm::normalize(glm::dvec3(0, -0.1, 0) - eye));
    worst_aim_deg =
        std::max(worst_aim_deg, std::acos(std::min(1.0, cos_aim)) * 180 / std::numbers::pi);
  }
  EXPECT_LT(worst_radius, 0.001);  // interior and across the seam: it is a closed loop
  EXPECT_LT(worst_height, 0.01);
  EXPECT_LT(worst_aim_deg, 0.5);
  RecordProperty("worst_radius_fraction", std::to_string(worst_radius));
  RecordProperty("worst_height", std::to_string(worst_height));
  RecordProperty("worst_aim_deg", std::to_string(worst_aim_deg));

  const CliRun r = run({"bench", "--frames", "2", "--runs", "1", "--size", "64x36"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("along " +
                       (std::filesystem::path(SOURCE_DIR) / "config" / "paths" / "benchmark.toml")
                           .lexically_normal()
                           .string()),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace fr
