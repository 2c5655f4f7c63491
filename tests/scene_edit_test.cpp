// The explorer's edit mode (app/scene_edit.hpp) on a project `fractalis new` made, driven as an
// author drives it, headless (the window adds nothing here): a saved .cl change is on screen
// without a C build (the sphere shrinks: fewer pixels hit); a broken edit keeps the last good DE
// rendering and names the user's file and line; the fix recovers; an endless loop in the DE is
// reported and undone within the short limit; a saved .c change is rebuilt and reloaded with the
// camera and values kept; a save storm is one change; a folder that vanishes is said and waited
// for. (Timings are the benchmark's, not asserted here.)
#include "app/explorer.hpp"
#include "app/scene_edit.hpp"
#include "cli_run.hpp"
#include "io/run_program.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>

namespace fr {
namespace {

using clock_type = std::chrono::steady_clock;

std::string read(const std::filesystem::path& file) {
  return test::read_file(file);
}
void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "no '" << from << "' in the file";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class SceneEditTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root = test::fresh_dir("scene_edit");
    test::set_environment("XDG_DATA_HOME", (root / "data").string());
    dir = root / "edit_blob";
    const test::CliRun made = test::run({"new", "edit_blob", "--dir", dir.string()});
    ASSERT_EQ(made.code, 0) << made.err;
    std::string error;
    const auto project = read_scene_project(dir, &error);
    ASSERT_TRUE(project) << error;
    EXPECT_EQ(project->scene_id, "edit_blob");
    EXPECT_EQ(project->de_file, "edit_blob.cl");
    // The explorer's own limits (a new DE's probe within 10 s), not the tests' long ones.
    worker = std::make_unique<RenderWorker>(test::runtime().device(),
                                            explorer_worker_limits(PluginPolicy{}));
    library = std::make_unique<SceneLibrary>(
        std::vector<std::filesystem::path>{root / "data" / "fractalis" / "scenes"}, PluginPolicy{},
        RenderSettings{}, *worker, &events);
    ASSERT_EQ(library->slots().size(), 1u);
    explorer = std::make_unique<Explorer>(Settings{}, *worker, *library, "edit_blob");
    edit = std::make_unique<SceneEdit>(*project, find_program_on_path("cmake"));
    start = clock_type::now();
  }
  void TearDown() override { test::set_environment("XDG_DATA_HOME", std::nullopt); }

  double now_s() const {
    return std::chrono::duration<double>(clock_type::now() - start).count();
  }
  // Frames until `done` holds or `limit_s` passed; the share of pixels hit in the last frame.
  bool frames_until(const std::function<bool()>& done, double limit_s) {
    const double until = now_s() + limit_s;
    while (now_s() < until) {
      // (The library's watcher reads the clock too: it reloads a plugin once it stopped changing.)
      explorer->update(input, 1.0 / 30, now_s());
      const int shown = edit->opencl_shown();
      edit->poll(*explorer, now_s());  // between update and render, as the explorer's loop does
      // The frame before this poll was a change's first, the quick build's.
      if (edit->opencl_shown() > shown) quick_hit = last_hit;
      if (const FrameView* f = explorer->render(96, 64); f && f->steps) last_hit = hit_share(*f);
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(15));
    }
    return false;
  }
  static double hit_share(const FrameView& f) {
    const RayCounts c = count_rays(f);
    return double(c.hit) / double(f.pixel_count());
  }

  std::filesystem::path root, dir;
  std::vector<SceneEvent> events;
  std::unique_ptr<RenderWorker> worker;
  std::unique_ptr<SceneLibrary> library;
  std::unique_ptr<Explorer> explorer;
  std::unique_ptr<SceneEdit> edit;
  InputState input;
  clock_type::time_point start;
  double last_hit = -1;
  double quick_hit = -1;  // the share of pixels hit in the last quick build's frame
};

TEST_F(SceneEditTest, OpenCLAndCEditsBreakagesAndRecovery) {
  // (The template's ripple moves with time: the view never stops refining; frames are waited for.)
  const auto frames_later = [&](uint64_t count) {
    const uint64_t until = explorer->frames_rendered() + count;
    return frames_until([&] { return explorer->frames_rendered() >= until; }, 60);
  };
  ASSERT_TRUE(frames_later(3));
  const double hit_before = last_hit;
  ASSERT_GT(hit_before, 0.05) << "the sphere is in view";
  explorer->current().state.camera.eye[0] += 0.25;  // the author's view, to be kept
  const fr_camera view = explorer->current().state.camera;
  const std::string good_cl = read(dir / "edit_blob.cl");

  // A .cl save: the radius halves. No C build runs; the picture changes (fewer pixels hit).
  write(dir / "edit_blob.cl", replaced(good_cl, "r - PARAM(radius)", "r - 0.5f * PARAM(radius)"));
  ASSERT_TRUE(frames_until([&] { return edit->opencl_applied() == 1; }, 60)) << edit->status();
  ASSERT_TRUE(frames_later(2));
  EXPECT_EQ(edit->c_builds(), 0);
  EXPECT_FALSE(edit->failed()) << edit->status();
  EXPECT_LT(last_hit, 0.6 * hit_before) << "a sphere of half the radius covers about a quarter";
  EXPECT_EQ(edit->opencl_shown(), 1) << "its first frame was the quick build's";
  EXPECT_NEAR(quick_hit, last_hit, 0.03) << "the quick build renders the same picture";
  EXPECT_NE(explorer->current().scene->info.de_source.find("0.5f * PARAM(radius)"), std::string::npos);
  const std::string smaller_cl = read(dir / "edit_blob.cl");

  // A broken save: the error names the user's file and line; the last good DE renders on.
  std::string broken = smaller_cl;
  broken.replace(broken.find("return"), 6, "return undeclared_name +");
  const size_t line = 1 + std::count(broken.begin(), broken.begin() + broken.find("undeclared"), '\n');
  write(dir / "edit_blob.cl", broken);
  ASSERT_TRUE(frames_until([&] { return edit->failed(); }, 60)) << edit->status();
  EXPECT_NE(edit->status().find("edit_blob.cl:" + std::to_string(line)), std::string::npos)
      << edit->status();
  EXPECT_EQ(explorer->current().scene->info.de_source, smaller_cl) << "the last good DE is back";
  const uint64_t frames = explorer->frames_rendered();
  explorer->mark_changed();
  ASSERT_TRUE(frames_until([&] { return explorer->frames_rendered() > frames; }, 30))
      << "it still renders";
  // The fix recovers.
  write(dir / "edit_blob.cl", good_cl);
  ASSERT_TRUE(frames_until([&] { return edit->opencl_applied() == 2; }, 60)) << edit->status();
  EXPECT_FALSE(edit->failed());

  // An endless loop: reported, undone, within the short limit.
  write(dir / "edit_blob.cl",
        replaced(good_cl, "const real_t r = v3_length(p);",
                 "real_t r = v3_length(p);\n  for (int i = 0; i < 1; i += 0) r = r * 1.0000001f + "
                 "to_real(1e-30f);"));
  const double hang_at = now_s();
  ASSERT_TRUE(frames_until([&] { return edit->failed(); }, 60)) << edit->status();
  const double reported_s = now_s() - hang_at;
  RecordProperty("hang_reported_s", std::to_string(reported_s));
  EXPECT_LT(reported_s, 15) << "reported within the short limit";
  EXPECT_EQ(explorer->current().scene->info.de_source, good_cl);
  write(dir / "edit_blob.cl", good_cl);

  // A save storm (ten saves a second for a second): one change, applied once it settles.
  const int applied = edit->opencl_applied();
  for (int i = 0; i < 10; ++i) {
    write(dir / "edit_blob.cl", replaced(good_cl, "r - PARAM(radius)",
                                         "r - " + std::to_string(0.5 + 0.01 * i) + "f * PARAM(radius)"));
    frames_until([] { return false; }, 0.1);
  }
  ASSERT_TRUE(frames_until([&] { return edit->opencl_applied() > applied && !edit->failed(); }, 60))
      << edit->status();
  frames_until([] { return false; }, 1.0);
  EXPECT_LE(edit->opencl_applied(), applied + 3) << "not one build per save";
  EXPECT_NE(explorer->current().scene->info.de_source.find("0.590000f"), std::string::npos)
      << "the storm's last text is what renders";

  // A .c save: rebuilt and reloaded, camera kept.
  write(dir / "edit_blob.c", replaced(read(dir / "edit_blob.c"), "A rippled sphere",
                                      "An edited sphere"));
  ASSERT_TRUE(frames_until(
      [&] { return explorer->current().scene->info.description.find("An edited sphere") == 0; },
      120))
      << edit->status();
  EXPECT_EQ(edit->c_builds(), 1);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(explorer->current().state.camera.eye[a], view.eye[a], 1e-9) << "the camera stays";
    EXPECT_NEAR(explorer->current().state.camera.target[a], view.target[a], 1e-9);
  }
  // A broken .c: the compiler's error with file and line; the scene renders on.
  write(dir / "edit_blob.c", replaced(read(dir / "edit_blob.c"), "static fr_result update(",
                                      "static fr_result update(((("));
  ASSERT_TRUE(frames_until([&] { return edit->failed(); }, 120)) << edit->status();
  EXPECT_NE(edit->status().find("edit_blob.c:"), std::string::npos) << edit->status();
  EXPECT_NE(edit->status().find("error"), std::string::npos) << edit->status();

  // The folder goes away and comes back.
  std::filesystem::rename(dir, root / "moved");
  ASSERT_TRUE(frames_until([&] { return edit->status().find("cannot be read") != std::string::npos; }, 5))
      << edit->status();
  const uint64_t before = explorer->frames_rendered();
  explorer->mark_changed();
  ASSERT_TRUE(frames_until([&] { return explorer->frames_rendered() > before; }, 30));
  std::filesystem::rename(root / "moved", dir);
  ASSERT_TRUE(frames_until([&] { return edit->status().find("is back") != std::string::npos; }, 5))
      << edit->status();
}

}  // namespace
}  // namespace fr
