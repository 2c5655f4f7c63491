// The mirror bounces' own step budgets (render.bounce_max_steps, render.bounce_shadow_max_steps):
// they change what mirrors show and nothing else — the primary rays' depth, normals, occlusion
// and shadow passes stay bit for bit the same, a frame without bounces renders the same image
// whatever the budgets (the primary rays never take the bounces' budgets), a budget of 0 shadow
// steps leaves the bounces without shadow rays at all, and a smaller one makes fewer of them.
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <string>

namespace fr {
namespace {

struct View {
  std::shared_ptr<const LoadedScene> scene;
  SceneState state;
};

View benchmark_view() {
  View v;
  v.scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "benchmark" PLUGIN_SUFFIX);
  v.state = make_default_state(v.scene->info);
  std::string error;
  auto instance = SceneInstance::create(v.scene, &error);
  EXPECT_TRUE(instance && instance->update(v.state, 0.0, &error)) << error;
  return v;
}

struct Counted {
  FrameImage image;
  EvalCounts counts;
};

Counted render(const View& v, int bounce_max_steps, int bounce_shadow_max_steps,
               int max_bounces = RenderSettings{}.max_bounces) {
  RenderSettings s;
  s.max_bounces = max_bounces;
  s.width_px = 96;
  s.height_px = 54;
  s.precision = Precision::Float;
  s.count_evaluations = true;
  s.bounce_max_steps = bounce_max_steps;
  s.bounce_shadow_max_steps = bounce_shadow_max_steps;
  Renderer renderer(test::runtime());
  Counted c;
  c.image = renderer.render(v.scene->info, v.state, s, true);
  c.counts = renderer.eval_counts();
  return c;
}

// Lane evaluations made by the bounces' shadow rays, per pixel.
double bounce_shadow_made(const EvalCounts& counts) {
  double made = 0;
  for (const StageCount& r : stage_counts(counts))
    if (r.bounce > 0 && r.stage.rfind("shadow", 0) == 0) made += r.made_per_pixel;
  return made;
}

void expect_same_primary_passes(const FrameImage& a, const FrameImage& b, const std::string& what) {
  EXPECT_EQ(a.depth, b.depth) << what;
  EXPECT_EQ(a.normal, b.normal) << what;
  EXPECT_EQ(a.occlusion, b.occlusion) << what;
  EXPECT_EQ(a.shadow, b.shadow) << what;
  EXPECT_EQ(a.ray_status, b.ray_status) << what;
}

TEST(BounceBudgets, ChangeOnlyWhatMirrorsShow) {
  const View v = benchmark_view();
  const Counted full = render(v, 160, 32);
  const Counted no_shadows = render(v, 160, 0);
  const Counted short_march = render(v, 1, 32);
  expect_same_primary_passes(full.image, no_shadows.image, "no shadows at the bounces");
  expect_same_primary_passes(full.image, short_march.image, "one march step at the bounces");
  // The mirrors show something else (the budgets are not ignored).
  EXPECT_GT(test::pixels_differing(full.image.rgba8, no_shadows.image.rgba8, 2), 0);
  EXPECT_GT(test::pixels_differing(full.image.rgba8, short_march.image.rgba8, 2), 0);
}

TEST(BounceBudgets, WithoutBouncesNoDifference) {
  const View v = benchmark_view();
  const Counted full = render(v, 160, 32, 0);
  const Counted budgets = render(v, 1, 0, 0);
  EXPECT_EQ(full.image.rgba8, budgets.image.rgba8);
  EXPECT_EQ(full.image.linear_rgba, budgets.image.linear_rgba);
}

TEST(BounceBudgets, ShadowStepsBoundTheBouncesShadowWork) {
  const View v = benchmark_view();
  const double made_32 = bounce_shadow_made(render(v, 160, 32).counts);
  const double made_16 = bounce_shadow_made(render(v, 160, 16).counts);
  const double made_0 = bounce_shadow_made(render(v, 160, 0).counts);
  std::printf("bounce shadow rays, lane evaluations made per pixel: 32 steps %.3f, 16 steps %.3f\n",
              made_32, made_16);
  EXPECT_GT(made_32, 0.0) << "the benchmark scene's mirrors should see lit surfaces";
  EXPECT_LT(made_16, made_32);
  EXPECT_EQ(made_0, 0.0) << "0 steps: no shadow rays at the bounces";
}

}  // namespace
}  // namespace fr
