// The per-stage DE counters (kernels/eval_counts.cl, render/eval_counts.hpp): checked against
// independent counts — the per-pixel step output the march writes, the hit mask times the
// evaluations a normal costs, one lane per packet — and, per in-tree scene, pinned for a few
// fixed views so that a change that silently makes rendering do more work fails here, with no
// timing involved (the counts are deterministic).
#include "app/explorer.hpp"
#include "cli/explorer_setup.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <cmath>
#include <numeric>

namespace fr {
namespace {

struct Counted {
  FrameImage image;
  EvalCounts counts;
};

Counted render_counted(const std::shared_ptr<const LoadedScene>& scene, SceneState state,
                       RenderSettings s) {
  s.count_evaluations = true;
  Renderer renderer(test::runtime());
  Counted c;
  c.image = renderer.render(scene->info, state, s, true);
  c.counts = renderer.eval_counts();
  return c;
}

const StageCount* find_stage(const std::vector<StageCount>& rows, int bounce,
                             const std::string& stage) {
  for (const auto& r : rows)
    if (r.bounce == bounce && r.stage == stage) return &r;
  return nullptr;
}

RenderSettings small(int lanes) {
  RenderSettings s;
  s.width_px = 64;
  s.height_px = 48;
  s.lanes = lanes;
  s.precision = Precision::Float;
  return s;
}

class UnitBallCounts : public ::testing::TestWithParam<int> {};

// The march's evaluations are its per-pixel step counts summed; the normals' are six (central
// differences) per hit pixel; with one lane, every packet evaluation is wanted.
TEST_P(UnitBallCounts, AgreeWithTheStepsAndTheHits) {
  const int lanes = GetParam();
  auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const Counted c = render_counted(scene, make_default_state(scene->info), small(lanes));
  const auto rows = stage_counts(c.counts);
  const double pixels = double(c.image.steps.size());
  ASSERT_EQ(pixels, 64.0 * 48.0);
  const RayCounts rays = count_rays(c.image);
  ASSERT_EQ(rays.out_of_steps, 0u);
  ASSERT_GT(rays.hit, 100u);

  const StageCount* march = find_stage(rows, 0, "march");
  ASSERT_NE(march, nullptr);
  const double steps = std::accumulate(c.image.steps.begin(), c.image.steps.end(), 0.0);
  EXPECT_DOUBLE_EQ(march->evals_per_pixel * pixels, steps);

  const StageCount* normals = find_stage(rows, 0, "normals");
  ASSERT_NE(normals, nullptr);
  EXPECT_DOUBLE_EQ(normals->evals_per_pixel * pixels, 6.0 * double(rays.hit));

  // The unit ball has no surface source, no shadows, no reflections, and step-count AO: the
  // march, the normals and the cone pre-pass (one cone per 8x8 pixels) are all there is.
  EXPECT_EQ(rows.size(), 3u);
  const StageCount* cone = find_stage(rows, 0, "cone pre-pass");
  ASSERT_NE(cone, nullptr);
  EXPECT_LT(cone->evals_per_pixel, march->evals_per_pixel);
  for (const auto& r : rows) {
    EXPECT_GT(r.utilisation, 0.0) << r.stage;
    EXPECT_LE(r.utilisation, 1.0) << r.stage;
    // Made: the packets' evaluations times their width, at least what the lanes wanted.
    EXPECT_NEAR(r.made_per_pixel * r.utilisation, r.evals_per_pixel, 1e-9) << r.stage;
    if (lanes == 1) {
      EXPECT_DOUBLE_EQ(r.utilisation, 1.0) << r.stage;
      EXPECT_DOUBLE_EQ(r.made_per_pixel, r.evals_per_pixel) << r.stage;
    }
  }
  // The normals are made once per packet with a hit, six evaluations for each of its lanes.
  const auto normals_made = std::llround(normals->made_per_pixel * pixels);
  EXPECT_NEAR(normals->made_per_pixel * pixels, static_cast<double>(normals_made), 1e-6);
  EXPECT_EQ(normals_made % (6 * lanes), 0) << normals_made;
  // Packets of 16 or 64 rays along the sphere's silhouette carry lanes that are already done.
  if (lanes > 1) {
    EXPECT_LT(march->utilisation, 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Lanes, UnitBallCounts, ::testing::Values(1, 16, 64),
                         [](const auto& info) { return "lanes" + std::to_string(info.param); });

TEST(EvalCounts, OffCountsNothingAndChangesNoPixel) {
  auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  const SceneState state = make_default_state(scene->info);
  Renderer renderer(test::runtime());
  const FrameImage plain = renderer.render(scene->info, state, small(16), true);
  EXPECT_EQ(renderer.eval_counts().samples, 0);
  EXPECT_EQ(total_evals_per_pixel(renderer.eval_counts()), 0.0);
  const Counted counted = render_counted(scene, state, small(16));
  EXPECT_EQ(plain.rgba8, counted.image.rgba8);
  EXPECT_EQ(plain.depth, counted.image.depth);
}

// Every sample is counted, and the figures are per pixel per sample.
TEST(EvalCounts, SamplesAreAveraged) {
  auto scene = test::unit_ball();
  ASSERT_TRUE(scene);
  RenderSettings one = small(16), four = small(16);
  four.samples = 4;
  const Counted a = render_counted(scene, make_default_state(scene->info), one);
  const Counted b = render_counted(scene, make_default_state(scene->info), four);
  EXPECT_EQ(b.counts.samples, 4);
  // Jittered samples hit slightly different points: the same work per sample within 5%.
  EXPECT_NEAR(total_evals_per_pixel(b.counts), total_evals_per_pixel(a.counts),
              0.05 * total_evals_per_pixel(a.counts));
}

// Each lane of a packet is its own ray: the evaluations rays ask for do not depend on how many
// share a packet (up to float contraction differences between the scalar and vector code).
TEST(EvalCounts, ActiveEvaluationsDoNotDependOnTheLaneWidth) {
  auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  const SceneState state = make_default_state(scene->info);
  const Counted one = render_counted(scene, state, small(1));
  const Counted sixteen = render_counted(scene, state, small(16));
  EXPECT_NEAR(total_evals_per_pixel(one.counts), total_evals_per_pixel(sixteen.counts),
              0.01 * total_evals_per_pixel(one.counts));
  EXPECT_DOUBLE_EQ(total_utilisation(one.counts), 1.0);
  EXPECT_LT(total_utilisation(sixteen.counts), 1.0);
}

// The explorer's overlay shows the counts of its last full frame while counting is on, and none
// otherwise (the plain kernel).
TEST(EvalCounts, ExplorerCountsWhileAsked) {
  ParsedOptions options;
  options.values["scene"] = {"mandelbulb"};
  options.values["size"] = {"64x48"};
  options.values["plugins"] = {SCENE_PLUGIN_DIR};
  ExplorerSetup setup = prepare_explorer(options);
  Explorer& explorer = *setup.explorer;
  ASSERT_NE(explorer.render(64, 48), nullptr);
  EXPECT_EQ(explorer.stats().eval_counts.samples, 0);
  explorer.set_count_evaluations(true);
  ASSERT_NE(explorer.render(64, 48), nullptr);
  EXPECT_GT(total_evals_per_pixel(explorer.stats().eval_counts), 1.0);
  const std::vector<StageCount> rows = stage_counts(explorer.stats().eval_counts);
  EXPECT_NE(find_stage(rows, 0, "normals"), nullptr);
  explorer.set_count_evaluations(false);
  EXPECT_EQ(explorer.stats().eval_counts.samples, 0);
}

// The work each in-tree scene's frames take, pinned: a view of the scene's default camera at
// 128x72 with every effect it declares. `now` is what this revision measured; a change that
// makes the renderer do more than 3% more work fails, and one that makes it do much less must
// update the figure here (and say so in docs/performance.md).
struct PinnedView {
  const char* scene;
  double evals_per_pixel;  // all stages, per pixel
  double march_per_pixel;  // primary march alone
  // Lane evaluations made, all stages, per pixel: a packet runs at its slowest lane's pace, so a
  // change can want fewer evaluations and still make more (docs/performance.md).
  double made_per_pixel;
};

class PinnedCounts : public ::testing::TestWithParam<PinnedView> {};

TEST_P(PinnedCounts, NoMoreWorkThanPinned) {
  const PinnedView& v = GetParam();
  auto scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) /
                                  (std::string(v.scene) + PLUGIN_SUFFIX));
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  ASSERT_TRUE(instance && instance->update(state, 0.0, &error)) << error;
  RenderSettings s;
  s.width_px = 128;
  s.height_px = 72;
  s.lanes = 16;
  s.precision = Precision::Float;
  const Counted c = render_counted(scene, state, s);
  const std::vector<StageCount> rows = stage_counts(c.counts);
  const StageCount* march = find_stage(rows, 0, "march");
  ASSERT_NE(march, nullptr);
  std::printf("%s: %.3f evaluations per pixel, primary march %.3f, lane evaluations made %.3f\n",
              v.scene, total_evals_per_pixel(c.counts), march->evals_per_pixel,
              total_made_per_pixel(c.counts));
  EXPECT_LE(total_evals_per_pixel(c.counts), 1.03 * v.evals_per_pixel);
  EXPECT_LE(march->evals_per_pixel, 1.03 * v.march_per_pixel);
  EXPECT_LE(total_made_per_pixel(c.counts), 1.03 * v.made_per_pixel);
  EXPECT_GE(total_made_per_pixel(c.counts), 0.9 * v.made_per_pixel);
  // Far fewer means the pins are stale (or counting broke): update them with the change.
  EXPECT_GE(total_evals_per_pixel(c.counts), 0.9 * v.evals_per_pixel);
}

INSTANTIATE_TEST_SUITE_P(InTreeScenes, PinnedCounts,
                         ::testing::Values(PinnedView{"mandelbulb", 3.967, 1.992, 5.681},
                                           PinnedView{"menger", 10.773, 3.978, 14.837},
                                           PinnedView{"sierpinski", 9.102, 5.148, 18.066},
                                           PinnedView{"julia", 11.933, 5.928, 18.168},
                                           PinnedView{"benchmark", 44.590, 7.122, 76.333}),
                         [](const auto& info) { return std::string(info.param.scene); });

}  // namespace
}  // namespace fr
