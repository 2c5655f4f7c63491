// The benchmark's statistics on a fake clock: known frame times in, known figures out.
#include "bench/bench_report.hpp"
#include "bench/frame_stats.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <limits>

namespace fr {
namespace {

// The one percentile (bench's frame times, sweep's pixel errors): nearest rank on the percent
// scale, 0 for no values.
TEST(BenchStats, PercentileIsNearestRankOnThePercentScale) {
  EXPECT_EQ(percentile({5, 1, 4, 2, 3}, 50), 3);
  EXPECT_EQ(percentile({5, 1, 4, 2, 3}, 95), 5);
  EXPECT_EQ(percentile({5, 1, 4, 2, 3}, 0), 1);
  EXPECT_EQ(percentile({5, 1, 4, 2, 3}, 100), 5);
  EXPECT_EQ(percentile({5, 1, 4, 2, 3}, 40), 2);  // 2 of 5 at or below
  EXPECT_EQ(percentile({}, 50), 0);
}

TEST(BenchStats, FakeClockFrameTimes) {
  // A clock that advances by a scripted duration each time a frame renders.
  const std::vector<double> scripted = {20, 10, 40, 30, 50, 10, 20, 30, 20, 70};
  double now = 1000;
  std::vector<int> rendered;
  auto frames = time_frames(
      static_cast<int>(scripted.size()), [&](int i) { rendered.push_back(i), now += scripted[i]; },
      [&] { return now; });
  EXPECT_EQ(frames, scripted);
  EXPECT_EQ(rendered, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));

  const FrameStats s = summarize_frames(frames);
  EXPECT_EQ(s.frames, 10u);
  EXPECT_DOUBLE_EQ(s.total_ms, 300);
  EXPECT_DOUBLE_EQ(s.min_ms, 10);
  EXPECT_DOUBLE_EQ(s.max_ms, 70);
  EXPECT_DOUBLE_EQ(s.mean_ms, 30);
  // Sorted: 10 10 20 20 20 30 30 40 50 70; nearest rank: p50 is the 5th, p95 the 10th.
  EXPECT_DOUBLE_EQ(s.p50_ms, 20);
  EXPECT_DOUBLE_EQ(s.p95_ms, 70);
  EXPECT_DOUBLE_EQ(s.mean_fps, 1000.0 / 30);
  EXPECT_DOUBLE_EQ(s.min_fps, 1000.0 / 70);
  EXPECT_DOUBLE_EQ(s.max_fps, 1000.0 / 10);
}

// With 20 frames the nearest-rank p95 is the 19th value, not the maximum, and p50 the 10th: an
// implementation returning max or the upper median fails here.
TEST(BenchStats, PercentilesAreNearestRank) {
  std::vector<double> frames;
  for (int i = 20; i >= 1; --i) frames.push_back(i);  // unsorted on purpose
  const FrameStats s = summarize_frames(frames);
  EXPECT_DOUBLE_EQ(s.p50_ms, 10);
  EXPECT_DOUBLE_EQ(s.p95_ms, 19);
  EXPECT_DOUBLE_EQ(s.max_ms, 20);
}

TEST(BenchStats, SingleFrameAndEmpty) {
  const FrameStats s = summarize_frames({16});
  EXPECT_DOUBLE_EQ(s.p50_ms, 16);
  EXPECT_DOUBLE_EQ(s.p95_ms, 16);
  EXPECT_DOUBLE_EQ(s.mean_fps, 62.5);
  EXPECT_THROW(summarize_frames({}), std::invalid_argument);
}

TEST(BenchStats, ReportFormats) {
  BenchReport r;
  r.scene_id = "benchmark";
  r.scene_version = "1.0.0";
  r.width_px = 1366;
  r.height_px = 768;
  r.runs = 2;
  r.frames_per_run = 3;
  r.stats = summarize_frames({10, 20, 30, 40, 50, 60});
  r.system.cpu_model = "Test \"CPU\"";
  r.system.logical_cores = 2;
  const std::string text = format_bench_text(r);
  EXPECT_NE(text.find("1366x768"), std::string::npos);
  EXPECT_NE(text.find("median 30.00 ms, min 10.00 ms, max 60.00 ms over 6 frames"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("p95 60.00 ms"), std::string::npos) << text;
  EXPECT_NE(text.find("fps: average 28.57, min 16.67, max 100.00"), std::string::npos) << text;
  // The JSON parses, and says what the report holds; a non-finite value (no frames: infinite
  // fps) is null, and text that is not UTF-8 is replaced, not an exception.
  const auto json = nlohmann::json::parse(format_bench_json(r));
  EXPECT_EQ(json["system"]["cpu"], "Test \"CPU\"");
  EXPECT_EQ(json["resolution"]["width"], 1366);
  EXPECT_EQ(json["resolution"]["height"], 768);
  EXPECT_EQ(json["frame_ms"]["p50"], 30.0);
  EXPECT_EQ(json["frame_ms"]["max"], 60.0);
  r.stats.max_fps = std::numeric_limits<double>::infinity();
  r.system.os = "bad \xff utf-8";
  const auto odd = nlohmann::json::parse(format_bench_json(r));
  EXPECT_TRUE(odd["fps"]["max"].is_null());
  EXPECT_EQ(odd["system"]["os"], "bad \xef\xbf\xbd utf-8");
}

}  // namespace
}  // namespace fr
