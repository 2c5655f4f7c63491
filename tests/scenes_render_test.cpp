// Every in-tree scene renders at 96x96 with no NaN or infinity, a sane hit fraction (its default
// view neither empty nor solid: 2% to 98% of the pixels hit), and shadow and occlusion factors
// inside [0, 1] — with every effect it declares on, in every mode, in float and in double.
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "in_tree_scenes.hpp"
#include "test_support.hpp"

#include <cmath>

namespace fr {
namespace {

struct Frame {
  FrameImage image;
  double hit_fraction = 0;
};

Frame render_scene(const std::string& id, const RenderSettings& base) {
  auto scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  SceneState state = make_default_state(scene->info);
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  EXPECT_TRUE(instance && instance->update(state, 0.5, &error)) << error;
  RenderSettings s = base;
  s.width_px = 96;
  s.height_px = 96;
  Frame f{Renderer(test::runtime()).render(scene->info, state, s, true), 0};
  size_t hits = 0;
  for (float d : f.image.depth) hits += std::isfinite(d);
  f.hit_fraction = double(hits) / double(f.image.depth.size());
  return f;
}

void expect_sane(const Frame& f, const std::string& what) {
  size_t bad = 0, out_of_range = 0;
  for (float v : f.image.linear_rgba) bad += !std::isfinite(v) || v < 0;
  for (size_t i = 0; i < f.image.occlusion.size(); ++i) {
    const float ao = f.image.occlusion[i], sh = f.image.shadow[i];
    out_of_range += !(ao >= 0 && ao <= 1) || !(sh >= 0 && sh <= 1);
  }
  EXPECT_EQ(bad, 0u) << what << ": NaN, infinite or negative colour values";
  EXPECT_EQ(out_of_range, 0u) << what << ": shadow or occlusion factors outside [0, 1]";
  EXPECT_GT(f.hit_fraction, 0.02) << what;
  EXPECT_LT(f.hit_fraction, 0.98) << what;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, DefaultSettings) {
  expect_sane(render_scene(GetParam(), RenderSettings{}), GetParam());
}

TEST_P(EveryScene, FloatAndDouble) {
  for (Precision precision : {Precision::Float, Precision::Double}) {
    RenderSettings s;
    s.precision = precision;
    expect_sane(render_scene(GetParam(), s),
                GetParam() + (precision == Precision::Float ? " (float)" : " (double)"));
  }
}

TEST_P(EveryScene, AlternativeModesAndAntiAliasing) {
  RenderSettings s;
  s.shading = ShadingModel::OrenNayar;
  s.normals = NormalMethod::CentralDifferences;
  s.ao_method = AoMethod::Sampled;
  s.shadow_method = ShadowMethod::Hard;
  s.fog_method = FogMethod::PowerLaw;
  s.samples = 3;
  s.aperture_radius = 0.02f;
  expect_sane(render_scene(GetParam(), s), std::string(GetParam()) + " (alternative modes)");
}

TEST_P(EveryScene, LambertShading) {
  RenderSettings s;
  s.shading = ShadingModel::Lambert;
  expect_sane(render_scene(GetParam(), s), std::string(GetParam()) + " (Lambert)");
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(test::scene_ids_for_this_platform()),
                         [](const auto& info) { return info.param; });

// Shadows darken: switching them on never raises a pixel's first-light factor and puts many hit
// pixels in shadow (the benchmark scene has objects standing on a floor). With them off, the
// factor is 1 wherever the surface faces the light and 0 where it faces away.
TEST(Effects, ShadowsDarkenAndSwitchOff) {
  RenderSettings on;
  const Frame with = render_scene("benchmark", on);
  RenderSettings off = on;
  off.disabled_stages = FR_FEATURE_SHADOWS;
  const Frame without = render_scene("benchmark", off);
  size_t shadowed_with = 0, shadowed_without = 0, raised = 0, partial_without = 0;
  for (size_t i = 0; i < with.image.shadow.size(); ++i) {
    shadowed_with += with.image.shadow[i] < 0.5f;
    shadowed_without += without.image.shadow[i] < 0.5f;
    raised += with.image.shadow[i] > without.image.shadow[i] + 1e-6f;
    partial_without += without.image.shadow[i] != 0.0f && without.image.shadow[i] != 1.0f;
  }
  EXPECT_GT(shadowed_with, shadowed_without + 50);
  EXPECT_EQ(raised, 0u);
  EXPECT_EQ(partial_without, 0u);
}

// Progressive accumulation converges: the mean of N jittered samples of a static view differs
// from the single centred sample only at edges (anti-aliasing), not overall brightness.
TEST(Effects, AccumulationKeepsTheMean) {
  RenderSettings one;
  RenderSettings many = one;
  many.samples = 8;
  const Frame a = render_scene("menger", one), b = render_scene("menger", many);
  double sum_a = 0, sum_b = 0;
  for (size_t i = 0; i < a.image.linear_rgba.size(); i += 4) {
    sum_a += a.image.linear_rgba[i];
    sum_b += b.image.linear_rgba[i];
  }
  EXPECT_NEAR(sum_b / sum_a, 1.0, 0.05);
  // Edges are smoothed: some pixels change visibly, but only a minority (edges, not the image).
  const size_t changed = test::pixels_differing(a.image.rgba8, b.image.rgba8, 8);
  EXPECT_GT(changed, 96u * 96 / 100) << "no edge was smoothed";
  EXPECT_LT(changed, 96u * 96 / 2) << "anti-aliasing changed most of the image";
}

}  // namespace
}  // namespace fr
