// Kernel assembly: only the stages a scene needs (and the user left on) are in the source, the
// parameter block matches the table, specialised parameters are baked in — and what is
// assembled actually compiles.
#include "render/kernel_assembly.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <cstring>

namespace fr {
namespace {

bool contains(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

SceneInfo sphere_scene(fr_features features) {
  SceneInfo info;
  info.id = "sphere";
  info.de_source =
      "real_t scene_de(vec3_t p, __constant const scene_params_t* params) {\n"
      "  return v3_length(p) - to_real(PARAM(radius));\n}\n";
  info.de_source_name = "sphere.cl";
  ParamInfo radius;
  radius.key = "radius";
  radius.type = FR_PARAM_FLOAT;
  radius.default_value.v[0] = 1;
  radius.max_value.v[0] = 2;
  info.params.push_back(radius);
  ParamInfo tint;
  tint.key = "tint";
  tint.type = FR_PARAM_COLOR;
  tint.flags = FR_PARAM_SPECIALIZE;
  tint.default_value = {{0.25, 0.5, 0.75}};
  tint.max_value = {{1, 1, 1}};
  info.params.push_back(tint);
  info.features = features;
  info.camera = fr_camera{sizeof(fr_camera), 0, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 45};
  info.bounding_radius = 2;
  return info;
}

TEST(KernelAssembly, MandelbulbHasNoShadowStage) {
  auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  const SceneInfo& info = scene->info;
  ASSERT_EQ(info.features & FR_FEATURE_SHADOWS, 0u) << "the Mandelbulb does not declare shadows";
  const auto state = make_default_state(info);
  const auto k =
      assemble_render_kernel(info, state.params, {16, Precision::Float, enabled_stages(info, 0)});
  EXPECT_FALSE(contains(k.source, "soft_shadow"));
  EXPECT_FALSE(contains(k.source, "#line 1 \"shadow.cl\""));
  EXPECT_TRUE(contains(k.source, "#define FR_STAGE_SHADOWS 0"));
  EXPECT_TRUE(contains(k.source, "step_count_ao"));
  EXPECT_TRUE(contains(k.source, "#line 1 \"mandelbulb.cl\""));
}

TEST(KernelAssembly, StageSwitchedOffByUserIsAbsent) {
  const SceneInfo info = sphere_scene(FR_FEATURE_AO | FR_FEATURE_SHADOWS);
  const auto values = make_default_state(info).params;
  const auto all =
      assemble_render_kernel(info, values, {1, Precision::Float, enabled_stages(info, 0)});
  EXPECT_TRUE(contains(all.source, "soft_shadow"));
  EXPECT_TRUE(contains(all.source, "step_count_ao"));
  const auto no_ao = assemble_render_kernel(
      info, values, {1, Precision::Float, enabled_stages(info, FR_FEATURE_AO)});
  EXPECT_TRUE(contains(no_ao.source, "soft_shadow"));
  EXPECT_FALSE(contains(no_ao.source, "step_count_ao"));
  EXPECT_TRUE(contains(no_ao.description, "stages: shadows"));
}

TEST(KernelAssembly, ParameterBlockAndSpecialisation) {
  const SceneInfo info = sphere_scene(0);
  auto values = make_default_state(info).params;
  const auto k = assemble_render_kernel(info, values, {16, Precision::Float, 0});
  EXPECT_TRUE(contains(k.source, "  float radius;\n"));
  EXPECT_FALSE(contains(k.source, "tint[3];")) << "a specialised parameter is not in the block";
  EXPECT_TRUE(contains(k.source, "#define FR_PARAM_radius ((scalar_t)params->radius)"));
  EXPECT_TRUE(contains(
      k.source,
      "#define FR_PARAM_tint v3s(((scalar_t)0.25f), ((scalar_t)0.5f), ((scalar_t)0.75f))"));
  // A new specialised value is a new source (and so a new cached program).
  values[1].v[0] = 0.125;
  const auto k2 = assemble_render_kernel(info, values, {16, Precision::Float, 0});
  EXPECT_NE(k.source, k2.source);
  EXPECT_TRUE(contains(k2.source, "((scalar_t)0.125f)"));

  const auto bytes = pack_scene_params(info, values);
  ASSERT_EQ(bytes.size(), 4u);
  float radius = 0;
  std::memcpy(&radius, bytes.data(), 4);
  EXPECT_EQ(radius, 1.0f);
}

TEST(KernelAssembly, LaneWidthAndPrecisionDefines) {
  const SceneInfo info = sphere_scene(0);
  const auto values = make_default_state(info).params;
  const auto k = assemble_render_kernel(info, values, {8, Precision::Double, 0});
  EXPECT_TRUE(contains(k.source, "#define FR_LANES 8\n"));
  EXPECT_TRUE(contains(k.source, "#define FR_DOUBLE 1\n"));
  EXPECT_FALSE(contains(k.source, "0.25f")) << "double literals carry no f suffix";
  EXPECT_EQ(tile_shape(16).width_px * tile_shape(16).height_px, 16);
  EXPECT_EQ(tile_shape(8).width_px * tile_shape(8).height_px, 8);
  EXPECT_EQ(tile_shape(1).width_px, 1);
}

// Every stage combination compiles at both widths, and the program cache builds each source once.
TEST(KernelAssembly, EveryStageCombinationCompiles) {
  const SceneInfo info = sphere_scene(FR_FEATURE_AO | FR_FEATURE_SHADOWS);
  SceneState state = make_default_state(info);
  state.camera = info.camera;
  Renderer renderer(test::runtime());
  RenderSettings settings;
  settings.width_px = 8;
  settings.height_px = 8;
  for (int lanes : {1, 16})
    for (fr_features off :
         {fr_features{0}, fr_features{FR_FEATURE_AO}, fr_features{FR_FEATURE_SHADOWS},
          fr_features{FR_FEATURE_AO | FR_FEATURE_SHADOWS}}) {
      settings.lanes = lanes;
      settings.disabled_stages = off;
      EXPECT_NO_THROW(renderer.render(info, state, settings))
          << "lanes " << lanes << " off " << off;
    }
  const size_t built = test::runtime().programs_built();
  settings.lanes = 16;
  settings.disabled_stages = 0;
  renderer.render(info, state, settings);
  EXPECT_EQ(test::runtime().programs_built(), built) << "a repeated frame must come from the cache";
}

}  // namespace
}  // namespace fr
