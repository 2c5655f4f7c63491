// The explorer with the path integrator chosen (issue 36's explorer point): frames while moving are
// the fast integrator's, a parked view accumulates path-traced samples up to explorer.path_samples,
// and the noise it reports left is the error it actually has against a long render of another
// seed. The noise estimate (app/noise_estimate.hpp) alone, on synthetic samples of known spread.
#include "app/explorer.hpp"
#include "app/noise_estimate.hpp"
#include "app/sample_bands.hpp"
#include "render/renderer.hpp"
#include "test_paths.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace fr {
namespace {

// Pixels of different means and spreads, averaged progressively: the estimate after n samples
// against the true RMS standard error, sqrt(mean of sigma_i^2 / n).
TEST(NoiseEstimate, RecoversTheStandardErrorOfKnownSamples) {
  const size_t pixels = 20000;
  std::mt19937 random(12345);
  std::normal_distribution<double> unit;
  std::vector<double> mean_of(pixels), sigma_of(pixels);
  double variance_sum = 0;
  for (size_t i = 0; i < pixels; ++i) {
    mean_of[i] = 0.2 + 0.6 * static_cast<double>(i % 97) / 97;
    sigma_of[i] = 0.05 + 0.3 * static_cast<double>(i % 31) / 31;
    variance_sum += 3 * sigma_of[i] * sigma_of[i];
  }
  std::vector<float> before(4 * pixels, 0), after(4 * pixels, 0);
  for (int n = 1; n <= 64; ++n) {
    before = after;
    for (size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) {
        const double x = mean_of[i] + sigma_of[i] * unit(random);
        after[4 * i + c] += static_cast<float>((x - after[4 * i + c]) / n);
      }
    const auto e = estimate_noise(before.data(), after.data(), pixels, n);
    if (n < 2) {
      EXPECT_FALSE(e.has_value()) << "one sample says nothing of its spread";
      continue;
    }
    ASSERT_TRUE(e.has_value());
    const double truth = std::sqrt(variance_sum / (3.0 * pixels) / n);
    EXPECT_NEAR(e->standard_error, truth, 0.03 * truth) << n << " samples";
  }
  EXPECT_FALSE(estimate_noise(before.data(), after.data(), 0, 5).has_value());
}

// Renders until the explorer shows something new (a path-traced sample renders in bands and,
// filtered, its filter's passes too: calls that show nothing); counts those calls in *between.
const FrameView* render_until_shown(Explorer& explorer, int w, int h, int* between = nullptr) {
  for (int call = 0; call < 200; ++call) {
    if (const FrameView* frame = explorer.render(w, h)) return frame;
    if (between) ++*between;
    if (explorer.stats().refined) return nullptr;
  }
  return nullptr;
}

// Values of `shown` (the explorer's linear picture of `samples` samples at w x h) that differ
// from a render of as many samples with the explorer's settings, filtered or not (the
// independent answer).
size_t values_unlike_a_render(Explorer& explorer, int w, int h, int samples, bool denoise,
                              const std::vector<float>& shown) {
  RenderSettings s = explorer.render_settings();
  s.width_px = w;
  s.height_px = h;
  s.samples = samples;
  s.denoise = denoise;
  Renderer renderer(test::runtime());
  const FrameImage whole = render_all_samples(renderer, explorer.current().scene->info,
                                              explorer.current().state, s, true);
  if (whole.linear_rgba.size() != shown.size())
    return std::max(whole.linear_rgba.size(), shown.size());
  size_t differing = 0;
  for (size_t i = 0; i < shown.size(); ++i) differing += shown[i] != whole.linear_rgba[i];
  return differing;
}

TEST(ExplorerPath, FliesFastThenPathTracesTheParkedView) {
  const auto dir = test::folder_of_one_scene("path_plugins", TEST_SCENE_DIR, "unit_ball");
  std::vector<SceneEvent> events;
  SceneLibrary library({dir}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
  ASSERT_EQ(library.slots().size(), 1u);
  Settings settings;
  settings.render.integrator = Integrator::Path;
  settings.explorer.path_samples = 16;
  // The noise figure is the unfiltered mean's (with the filter on, none is shown: below).
  settings.explorer.denoise = false;
  Explorer explorer(settings, test::worker(), library, "unit_ball");
  const int w = 48, h = 32;
  // The first frame follows a change (the scene was just opened): the fast integrator.
  ASSERT_NE(explorer.render(w, h), nullptr);
  EXPECT_EQ(explorer.stats().path_samples, 0);
  std::vector<float> shown;
  double reported = 0;
  for (int n = 1; n <= 16; ++n) {
    const FrameView* frame = explorer.render(w, h);
    ASSERT_NE(frame, nullptr) << n;
    EXPECT_EQ(explorer.stats().path_samples, n);
    EXPECT_EQ(explorer.stats().path_noise.has_value(), n >= 2) << n;
    ASSERT_NE(frame->linear_rgba, nullptr);
    if (n == 16) {
      shown.assign(frame->linear_rgba, frame->linear_rgba + 4 * frame->pixel_count());
      reported = *explorer.stats().path_noise;
    }
  }
  EXPECT_EQ(explorer.render(w, h), nullptr) << "16 samples: the view is done";

  // What the noise really is: the shown mean against 1024 samples of another seed.
  RenderSettings s = explorer.render_settings();
  s.width_px = w;
  s.height_px = h;
  s.samples = 1024;
  s.seed = 1;
  Renderer renderer(test::runtime());
  const FrameImage reference = render_all_samples(renderer, explorer.current().scene->info,
                                                  explorer.current().state, s, true);
  double error2 = 0, sum = 0;
  for (size_t i = 0; i < shown.size(); ++i) {
    if (i % 4 == 3) continue;
    error2 += std::pow(shown[i] - reference.linear_rgba[i], 2.0);
    sum += shown[i];
  }
  const double values = static_cast<double>(shown.size() / 4 * 3);
  const double actual = std::sqrt(error2 / values) / (sum / values);
  ASSERT_GT(actual, 0);
  // The reference's own noise adds sqrt(16 / 1024) of the error in quadrature (0.8%); one frame's
  // estimate scatters by a few per cent at this size.
  EXPECT_NEAR(reported, actual, 0.15 * actual) << "reported " << reported << ", actual " << actual;

  // Moving again: fast frames, no path samples.
  InputState input;
  input.held.insert(Action::MoveForward);
  explorer.update(input, 0.05, 1.0);
  ASSERT_NE(explorer.render(w, h), nullptr);
  EXPECT_EQ(explorer.stats().path_samples, 0);
}

// A view too tall for one band (app/sample_bands.hpp): the explorer answers between bands, showing
// nothing new until a sample is whole, and what it then shows is the whole image's samples, byte
// for byte (a render of as many samples, the independent answer).
TEST(ExplorerPath, ATallViewRefinesInBandsAsWholeSamplesWould) {
  const auto dir = test::folder_of_one_scene("path_band_plugins", TEST_SCENE_DIR, "unit_ball");
  std::vector<SceneEvent> events;
  SceneLibrary library({dir}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
  Settings settings;
  settings.render.integrator = Integrator::Path;
  settings.explorer.path_samples = 3;
  settings.explorer.denoise = false;
  Explorer explorer(settings, test::worker(), library, "unit_ball");
  const int w = 24, h = 4 * SampleBands::kInitialRows + 8;
  ASSERT_NE(explorer.render(w, h), nullptr);  // after the change: fast
  std::vector<float> shown;
  int between = 0;  // calls that rendered a band and showed nothing new
  for (int n = 1; n <= 3; ++n) {
    const FrameView* frame = nullptr;
    for (int call = 0; call < 100 && !frame; ++call) {
      frame = explorer.render(w, h);
      if (frame) break;
      ++between;
      EXPECT_EQ(explorer.stats().path_samples, n - 1) << "a sample in bands counts when whole";
      EXPECT_FALSE(explorer.stats().refined);
    }
    ASSERT_NE(frame, nullptr) << n;
    EXPECT_EQ(explorer.stats().path_samples, n);
    ASSERT_NE(frame->linear_rgba, nullptr);
    if (n == 3) shown.assign(frame->linear_rgba, frame->linear_rgba + 4 * frame->pixel_count());
  }
  // The first sample: 64 rows, 64 more (the first timed band lets the next grow), at most 128,
  // then the rest.
  EXPECT_GE(between, 3);
  EXPECT_EQ(explorer.render(w, h), nullptr);
  EXPECT_TRUE(explorer.stats().refined);
  EXPECT_EQ(values_unlike_a_render(explorer, w, h, 3, false, shown), 0u);
}

// With explorer.denoise (on by default) the parked path-traced view is filtered: the overlay
// says so and shows no noise figure (the estimate reads the plain running mean's steps).
TEST(ExplorerPath, TheDenoisedPreviewSaysSo) {
  const auto dir = test::folder_of_one_scene("path_denoise_plugins", TEST_SCENE_DIR, "unit_ball");
  std::vector<SceneEvent> events;
  SceneLibrary library({dir}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
  Settings settings;
  settings.render.integrator = Integrator::Path;
  settings.explorer.path_samples = 3;
  ASSERT_TRUE(settings.explorer.denoise) << "on by default";
  Explorer explorer(settings, test::worker(), library, "unit_ball");
  ASSERT_NE(explorer.render(48, 32), nullptr);  // after the change: fast
  EXPECT_FALSE(explorer.stats().path_denoised);
  std::vector<float> shown;
  for (int n = 1; n <= 3; ++n) {
    int between = 0;
    const FrameView* frame = render_until_shown(explorer, 48, 32, &between);
    ASSERT_NE(frame, nullptr) << n;
    // The sample, then the filter's five passes, each queued by a call of its own.
    EXPECT_EQ(between, 1 + Renderer::kDenoisePasses) << n;
    EXPECT_EQ(explorer.stats().path_samples, n);
    EXPECT_TRUE(explorer.stats().path_denoised);
    EXPECT_FALSE(explorer.stats().path_noise.has_value());
    ASSERT_NE(frame->linear_rgba, nullptr);
    if (n == 3) shown.assign(frame->linear_rgba, frame->linear_rgba + 4 * frame->pixel_count());
  }
  // What it shows is the filter's picture of three samples, as `render` filters it at the end.
  EXPECT_EQ(values_unlike_a_render(explorer, 48, 32, 3, true, shown), 0u);
}

}  // namespace
}  // namespace fr
