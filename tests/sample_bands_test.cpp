// A path-traced sample rendered in bands of rows (render_settings.hpp, RowBand; the explorer's
// refinement, app/sample_bands.hpp): each pixel gets what the whole image's sample gives it, byte
// for byte (the independent answer: the same samples rendered whole); a band that is not one is
// refused; the bands cover every row once a sample and follow the time they take.
#include "app/sample_bands.hpp"
#include "app/frame_controller.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

namespace fr {
namespace {

TEST(SampleBands, CoverEveryRowOnceASample) {
  SampleBands bands(30);
  for (int sample = 0; sample < 3; ++sample) {
    int row = 0;
    for (int n = 0; n < 100; ++n) {
      const SampleBand b = bands.next(sample, 150);
      EXPECT_EQ(b.rows.first_row_px, row) << sample;
      EXPECT_EQ(b.rows.first_row_px % kRowBandAlign, 0);
      EXPECT_GT(b.rows.rows_px, 0);
      row += b.rows.rows_px;
      EXPECT_EQ(b.last, row == 150);
      if (b.last) break;
      EXPECT_EQ(b.rows.rows_px % kRowBandAlign, 0);
    }
    EXPECT_EQ(row, 150) << sample;
  }
  // Another height, or a reset, starts the sample again from the top.
  EXPECT_EQ(bands.next(3, 150).rows.first_row_px, 0);
  EXPECT_EQ(bands.next(3, 100).rows.first_row_px, 0);
  EXPECT_EQ(bands.next(3, 100).rows.first_row_px, SampleBands::kInitialRows);
  bands.reset();
  EXPECT_EQ(bands.next(3, 100).rows.first_row_px, 0);
}

TEST(SampleBands, AimAtTheTargetTime) {
  SampleBands bands(30);
  ASSERT_EQ(bands.rows_per_band(), 64);
  bands.measured(64, 60);  // twice the target: half the rows
  EXPECT_EQ(bands.rows_per_band(), 32);
  bands.measured(32, 960);  // far too slow: at most halved a measurement
  EXPECT_EQ(bands.rows_per_band(), 16);
  bands.measured(16, 960);  // never below one alignment's rows
  EXPECT_EQ(bands.rows_per_band(), kRowBandAlign);
  bands.measured(16, 1);  // far too fast: at most doubled
  EXPECT_EQ(bands.rows_per_band(), 32);
  bands.measured(32, 20);  // 48 rows would take 30 ms
  EXPECT_EQ(bands.rows_per_band(), 48);
  // A time that is only a bound from above lets the bands grow, never shrink.
  bands.measured(48, 300, true);
  EXPECT_EQ(bands.rows_per_band(), 48);
  bands.measured(48, 15, true);
  EXPECT_EQ(bands.rows_per_band(), 96);
  // Nonsense times say nothing.
  bands.measured(48, 0);
  bands.measured(48, -5);
  bands.measured(0, 10);
  EXPECT_EQ(bands.rows_per_band(), 96);
  for (int i = 0; i < 40; ++i) bands.measured(bands.rows_per_band(), 1e-3);
  EXPECT_EQ(bands.rows_per_band(), SampleBands::kMaxRows);
}

TEST(SampleBands, AnUnfinishedSampleIsPlannedAgain) {
  FrameController frames;
  frames.set_full_quality_samples(4);
  EXPECT_EQ(frames.plan(true).sample_index, 0);  // moving
  FramePlan p = frames.plan(false);
  EXPECT_TRUE(p.still);
  EXPECT_EQ(p.sample_index, 0);
  frames.sample_unfinished();
  EXPECT_EQ(frames.plan(false).sample_index, 0);
  EXPECT_EQ(frames.plan(false).sample_index, 1);
  frames.sample_unfinished();
  EXPECT_EQ(frames.plan(false).sample_index, 1);
  frames.sample_unfinished();
  frames.plan(true);           // a change starts over whatever was unfinished
  frames.sample_unfinished();  // (moving: nothing to hold)
  EXPECT_EQ(frames.plan(false).sample_index, 0);
}

// Two samples, whole and in bands of 16, 16, 16 and the last 24 rows (72 is not a multiple of the
// alignment), with the cone pre-pass on (a work-item's blocks span 32 rows: they straddle the
// bands) and off.
// The benchmark scene: its floor's wide bounds give the cone something to skip (the Mandelbulb's
// tight ones leave it nothing at this size).
void expect_bands_render_the_whole_sample(Integrator integrator, bool cone_prepass) {
  const auto scene =
      test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "benchmark" PLUGIN_SUFFIX);
  ASSERT_TRUE(scene);
  const SceneState state = make_default_state(scene->info);
  RenderSettings s;
  s.width_px = 64;
  s.height_px = 72;
  s.integrator = integrator;
  s.cone_prepass = cone_prepass;
  // Each on its own renderer, the bands' after a frame of another view (the camera three times as
  // far): what the bands do not compute themselves, the cone pre-pass's starts among them, would
  // start rays past the surface.
  Renderer whole_renderer(test::runtime()), renderer(test::runtime());
  FrameImage whole, banded;
  for (int i = 0; i < 2; ++i) whole_renderer.render_sample(scene->info, state, s, i);
  whole_renderer.finish(s, Readback::Everything, whole);
  SceneState farther = state;
  for (int a = 0; a < 3; ++a)
    farther.camera.eye[a] =
        state.camera.target[a] + 3 * (state.camera.eye[a] - state.camera.target[a]);
  renderer.render_sample(scene->info, farther, s, 0);
  for (int i = 0; i < 2; ++i)
    for (const RowBand rows : {RowBand{0, 16}, RowBand{16, 16}, RowBand{32, 16}, RowBand{48, 24}})
      renderer.render_sample(scene->info, state, s, i, Readback::Everything, rows);
  renderer.finish(s, Readback::Everything, banded);
  ASSERT_EQ(whole.linear_rgba.size(), banded.linear_rgba.size());
  size_t differing = 0;
  for (size_t i = 0; i < whole.linear_rgba.size(); ++i)
    differing += whole.linear_rgba[i] != banded.linear_rgba[i];
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(whole.depth, banded.depth);
  EXPECT_EQ(whole.steps, banded.steps);
  EXPECT_EQ(whole.rgba8, banded.rgba8);
  // And a band is all a call renders: the rows below it keep what they held.
  renderer.render_sample(scene->info, state, s, 0, Readback::Everything, RowBand{0, 16});
  FrameImage top;
  renderer.finish(s, Readback::Everything, top);
  const size_t row_values = 4 * static_cast<size_t>(s.width_px);
  EXPECT_NE(0, std::memcmp(top.linear_rgba.data(), banded.linear_rgba.data(),
                           16 * row_values * sizeof(float)))
      << "a new first sample replaced the top rows' mean of two";
  EXPECT_EQ(0, std::memcmp(top.linear_rgba.data() + 16 * row_values,
                           banded.linear_rgba.data() + 16 * row_values,
                           (72 - 16) * row_values * sizeof(float)));
}

TEST(RowBand, ASampleInBandsIsTheWholeSampleByteForByte) {
  expect_bands_render_the_whole_sample(Integrator::Path, true);
  expect_bands_render_the_whole_sample(Integrator::Path, false);
  expect_bands_render_the_whole_sample(Integrator::Fast, true);
}

// The denoiser's passes in bands (Renderer::denoise_rows) give what it gives the whole picture
// at once, byte for byte; passes out of order are refused.
TEST(RowBand, TheFilterInBandsIsTheWholeFilter) {
  const auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  const SceneState state = make_default_state(scene->info);
  RenderSettings s;
  s.width_px = 48;
  s.height_px = 72;
  s.integrator = Integrator::Path;
  s.denoise = true;
  Renderer renderer(test::runtime());
  FrameImage whole, banded, unfiltered;
  for (int i = 0; i < 2; ++i) renderer.render_sample(scene->info, state, s, i);
  renderer.finish(s, Readback::Everything, whole);
  for (int pass = 0; pass < Renderer::kDenoisePasses; ++pass)
    for (const RowBand rows : {RowBand{0, 32}, RowBand{32, 16}, RowBand{48, 24}})
      renderer.denoise_rows(s, pass, rows);
  renderer.finish(s, Readback::Everything, banded);
  EXPECT_EQ(whole.linear_rgba, banded.linear_rgba);
  EXPECT_EQ(whole.rgba8, banded.rgba8);
  RenderSettings plain = s;
  plain.denoise = false;
  renderer.finish(plain, Readback::Everything, unfiltered);
  EXPECT_NE(unfiltered.linear_rgba, banded.linear_rgba) << "the filter changed nothing";

  // Out of order: a later pass first, a band skipped, rows past the end.
  renderer.render_sample(scene->info, state, s, 2);
  EXPECT_THROW(renderer.denoise_rows(s, 1, RowBand{0, 32}), std::logic_error);
  EXPECT_THROW(renderer.denoise_rows(s, 0, RowBand{32, 16}), std::logic_error);
  renderer.denoise_rows(s, 0, RowBand{0, 32});
  EXPECT_THROW(renderer.denoise_rows(s, 0, RowBand{32, 48}), std::logic_error);
  // Half-way, a finish cannot filter (the passes' buffers hold a mix).
  EXPECT_THROW(renderer.finish(s, Readback::Display, banded), std::logic_error);
  // A new sample starts the filter over.
  renderer.render_sample(scene->info, state, s, 3);
  EXPECT_NO_THROW(renderer.finish(s, Readback::Display, banded));
}

TEST(RowBand, ABandThatIsNotOneIsRefused) {
  const auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const SceneState state = make_default_state(scene->info);
  RenderSettings s;
  s.width_px = 16;
  s.height_px = 40;
  Renderer renderer(test::runtime());
  for (const RowBand rows : {RowBand{8, 16}, RowBand{0, 48}, RowBand{16, 20}, RowBand{-16, 16},
                             RowBand{0, -16}, RowBand{48, 16}}) {
    try {
      renderer.render_sample(scene->info, state, s, 0, Readback::Everything, rows);
      ADD_FAILURE() << rows.first_row_px << " + " << rows.rows_px << " was rendered";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("not a band of a 16x40 image's rows"), std::string::npos)
          << e.what();
    }
  }
  // Through the render worker, the same refusal comes back as an error.
  EXPECT_THROW(
      test::worker().render_sample(scene->info, state, s, 0, Readback::Everything, RowBand{8, 16}),
      std::exception);
  // The last band may end the image whatever its height.
  EXPECT_NO_THROW(
      renderer.render_sample(scene->info, state, s, 0, Readback::Everything, RowBand{32, 8}));
  // (Waited for: a process that exits while PoCL still compiles the kernel for it crashes.)
  FrameImage image;
  renderer.finish(s, Readback::Display, image);
}

}  // namespace
}  // namespace fr
