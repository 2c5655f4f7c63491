// Kernel assembly: only the stages a scene needs (and the user left on) are in the source, the
// parameter block matches the table, specialised parameters are baked in — and what is
// assembled actually compiles.
#include "render/kernel_assembly.hpp"
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <glm/geometric.hpp>

#include <cmath>
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

// A function only each stage's file defines: its presence is the stage's code being there.
struct StageMarker {
  fr_features stage;
  const char* name;
  const char* code;
};
const StageMarker kStageMarkers[] = {
    {FR_FEATURE_SHADOWS, "shadows", "shadow_factors("},
    {FR_FEATURE_AO, "ao", "_ao(real_t"},
    {FR_FEATURE_GLOW, "glow", "add_glow("},
    {FR_FEATURE_FOG, "fog", "fog_amount("},
    {FR_FEATURE_REFLECTIONS, "reflections", "mirror_ray("},
    {kStageDepthOfField, "dof", "thin_lens("},
};

std::shared_ptr<const LoadedScene> scene_by_id(const std::string& id) {
  return test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
}

// For every in-tree scene and every effect: the stage's code is in the kernel exactly when the
// scene needs it and the user has not switched it off.
TEST(KernelAssembly, OnlyNeededStagesArePresentPerSceneAndSetting) {
  for (const char* id : {"mandelbulb", "menger", "sierpinski", "julia", "benchmark"}) {
    auto scene = scene_by_id(id);
    ASSERT_TRUE(scene) << id;
    const SceneInfo& info = scene->info;
    const auto values = make_default_state(info).params;
    for (const StageMarker& off : kStageMarkers) {
      for (bool user_off : {false, true}) {
        RenderSettings settings;
        settings.aperture_radius = 0.05f;  // depth of field on, unless switched off below
        if (user_off) settings.disabled_stages = off.stage;
        const KernelConfig config = make_kernel_config(info, settings, 16);
        const auto k = assemble_render_kernel(info, values, config);
        for (const StageMarker& m : kStageMarkers) {
          const bool needed = m.stage == kStageDepthOfField || (info.features & m.stage);
          const bool expected = needed && !(user_off && m.stage == off.stage);
          EXPECT_EQ(contains(k.source, m.code), expected)
              << id << ": stage " << m.name
              << (user_off ? " with " + std::string(off.name) + " off" : "");
        }
      }
    }
  }
}

TEST(KernelAssembly, MandelbulbHasNoShadowStage) {
  auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  const SceneInfo& info = scene->info;
  ASSERT_EQ(info.features & FR_FEATURE_SHADOWS, 0u) << "the Mandelbulb does not declare shadows";
  const auto state = make_default_state(info);
  const auto k =
      assemble_render_kernel(info, state.params, make_kernel_config(info, RenderSettings{}, 16));
  EXPECT_FALSE(contains(k.source, "shadow_factors"));
  EXPECT_FALSE(contains(k.source, "#line 1 \"shadow.cl\""));
  // Only shade.cl's empty fallback for the hook, not shadow.cl's definition.
  EXPECT_FALSE(
      contains(k.source, "#define FR_APPLY_SHADOWS(shadow, p, n, h, lights, facing, count) \\"));
  EXPECT_TRUE(contains(k.source, "step_count_ao"));
  EXPECT_TRUE(contains(k.source, "#line 1 \"mandelbulb.cl\""));
  EXPECT_TRUE(contains(k.source, "#line 1 \"fr/mandelbulb.cl\"")) << "the library file it includes";
  EXPECT_FALSE(contains(k.source, "fr/menger.cl")) << "nor any library file it does not";
}

TEST(KernelAssembly, LibraryIncludesExpandOnceAndUnknownOnesAreNamed) {
  SceneInfo info;
  info.id = "includer";
  info.de_source_name = "includer.cl";
  info.de_source =
      "#include \"fr/menger.cl\"\n#include \"fr/primitives.cl\"\n"
      "real_t scene_de(vec3_t p, __constant const scene_params_t* params) { return sd_sphere(p, "
      "1); }\n";
  const auto k = assemble_render_kernel(info, {}, KernelConfig{});
  size_t count = 0;
  for (size_t at = k.source.find("#line 1 \"fr/primitives.cl\""); at != std::string::npos;
       at = k.source.find("#line 1 \"fr/primitives.cl\"", at + 1))
    ++count;
  EXPECT_EQ(count, 1u) << "fr/primitives.cl is included by fr/menger.cl and again directly";
  EXPECT_TRUE(contains(k.source, "#line 3 \"includer.cl\""))
      << "line numbers resume after an include";
  info.de_source = "\n#include \"fr/nope.cl\"\n";
  try {
    assemble_render_kernel(info, {}, KernelConfig{});
    FAIL() << "an unknown library file was accepted";
  } catch (const KernelBuildError& e) {
    EXPECT_TRUE(
        contains(e.what(), "scene 'includer': includer.cl:2: unknown library file 'fr/nope.cl'"))
        << e.what();
  }
}

TEST(KernelAssembly, StageSwitchedOffByUserIsAbsent) {
  const SceneInfo info = sphere_scene(FR_FEATURE_AO | FR_FEATURE_SHADOWS);
  const auto values = make_default_state(info).params;
  RenderSettings settings;
  const auto all = assemble_render_kernel(info, values, make_kernel_config(info, settings, 1));
  EXPECT_TRUE(contains(all.source, "shadow_factors"));
  EXPECT_TRUE(contains(all.source, "step_count_ao"));
  settings.disabled_stages = FR_FEATURE_AO;
  const auto no_ao = assemble_render_kernel(info, values, make_kernel_config(info, settings, 1));
  EXPECT_TRUE(contains(no_ao.source, "shadow_factors"));
  EXPECT_FALSE(contains(no_ao.source, "step_count_ao"));
  EXPECT_TRUE(contains(no_ao.description, "stages: shadows"));
}

TEST(KernelAssembly, ParameterBlockAndSpecialisation) {
  const SceneInfo info = sphere_scene(0);
  auto values = make_default_state(info).params;
  const auto k = assemble_render_kernel(info, values, KernelConfig{16, Precision::Float});
  EXPECT_TRUE(contains(k.source, "  float radius;\n"));
  EXPECT_FALSE(contains(k.source, "tint[3];")) << "a specialised parameter is not in the block";
  EXPECT_TRUE(contains(k.source, "#define FR_PARAM_radius ((scalar_t)params->radius)"));
  EXPECT_TRUE(contains(
      k.source,
      "#define FR_PARAM_tint v3s(((scalar_t)0.25f), ((scalar_t)0.5f), ((scalar_t)0.75f))"));
  // A new specialised value is a new source (and so a new cached program).
  values[1].v[0] = 0.125;
  const auto k2 = assemble_render_kernel(info, values, KernelConfig{16, Precision::Float});
  EXPECT_NE(k.source, k2.source);
  EXPECT_TRUE(contains(k2.source, "((scalar_t)0.125f)"));

  // A number travels as its float and the rest in two more floats: a double kernel adds them
  // back to the double exactly.
  for (double v : {0.1, 1.3, -2.718281828459045, 1e-7, 12345.678901234567}) {
    values[0].v[0] = v;
    const auto bytes = pack_scene_params(info, values);
    ASSERT_EQ(bytes.size(), 12u);
    float radius[3] = {0, 0, 0};
    std::memcpy(radius, bytes.data(), 12);
    EXPECT_EQ(radius[0], static_cast<float>(v));
    EXPECT_EQ(double(radius[0]) + (double(radius[1]) + double(radius[2])), v) << v;
  }
  // A vec3's three components alike (GCC 12 at -O3 once dropped the rest of x and y): the block
  // holds x, y, z, then their mids, then their lows.
  SceneInfo with_vec3 = info;
  with_vec3.params[1].flags = 0;  // the tint travels in the block
  auto vec3_values = make_default_state(with_vec3).params;
  vec3_values[1] = {{1.8, -0.3, 1e-9 / 3}};
  const auto vec3_bytes = pack_scene_params(with_vec3, vec3_values);
  ASSERT_EQ(vec3_bytes.size(), 12u + 36u);
  float tint[9];
  std::memcpy(tint, vec3_bytes.data() + 12, sizeof tint);
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(double(tint[c]) + (double(tint[3 + c]) + double(tint[6 + c])), vec3_values[1].v[c])
        << "component " << c;

  const auto d = assemble_render_kernel(info, values, KernelConfig{16, Precision::Double});
  EXPECT_TRUE(contains(d.source, "  float radius;\n  float radius__mid;\n  float radius__lo;\n"));
  EXPECT_TRUE(contains(d.source,
                       "#define FR_PARAM_radius ((scalar_t)params->radius + ((scalar_t)params->"
                       "radius__mid + (scalar_t)params->radius__lo))"));
}

TEST(KernelAssembly, LaneWidthAndPrecisionDefines) {
  const SceneInfo info = sphere_scene(0);
  const auto values = make_default_state(info).params;
  const auto k = assemble_render_kernel(info, values, KernelConfig{8, Precision::Double});
  EXPECT_TRUE(contains(k.source, "#define FR_LANES 8\n"));
  EXPECT_TRUE(contains(k.source, "#define FR_DOUBLE 1\n"));
  EXPECT_FALSE(contains(k.source, "0.25f")) << "double literals carry no f suffix";
  EXPECT_EQ(tile_shape(16).width_px * tile_shape(16).height_px, 16);
  EXPECT_EQ(tile_shape(8).width_px * tile_shape(8).height_px, 8);
  EXPECT_EQ(tile_shape(1).width_px, 1);
}

// What a frame of the sphere scene must show whatever stages and modes are on: every colour
// finite and non-negative, and the hit mask of the analytic unit sphere (eye (0, 0, 4), 45
// degrees) — except within 1.5 pixels' angle of its rim, where the hit threshold and the thin
// lens's jitter may tip a pixel either way. Mutation caught: a march that reports no hits
// (march.cl returning `hit = active`) fails 14 of the 14 combinations.
void expect_sphere_frame(const FrameImage& img, const SceneInfo& info, const std::string& what) {
  const int w = img.width_px, h = img.height_px;
  const CameraRays rays = make_camera_rays(info.camera, w, h);
  int bad = 0, wrong_mask = 0, hits = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      for (int c = 0; c < 3; ++c) {
        const float v = img.linear_rgba[4 * i + c];
        bad += !std::isfinite(v) || v < 0;
      }
      const glm::dvec3 d = camera_ray_dir(rays, x, y);
      const double b = glm::dot(rays.eye, d);
      const double closest = std::sqrt(glm::dot(rays.eye, rays.eye) - b * b);
      if (std::abs(closest - 1) < 1.5 * rays.pixel_angle_rad * 4) continue;
      const bool analytic_hit = closest < 1;
      hits += analytic_hit;
      wrong_mask += analytic_hit != std::isfinite(img.depth[i]);
    }
  EXPECT_EQ(bad, 0) << what << ": NaN, infinite or negative colour values";
  EXPECT_GT(hits, w * h / 10) << what;
  EXPECT_EQ(wrong_mask, 0) << what << ": hit mask differs from the sphere's";
}

// Every stage and mode combination compiles at both widths and renders the sphere, and the
// program cache builds each source once.
TEST(KernelAssembly, EveryStageCombinationRendersTheSphere) {
  SceneInfo info = sphere_scene(FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_GLOW |
                                FR_FEATURE_FOG | FR_FEATURE_REFLECTIONS);
  SceneState state = make_default_state(info);
  Renderer renderer(test::runtime());
  RenderSettings settings;
  settings.width_px = 24;
  settings.height_px = 24;
  settings.aperture_radius = 0.01f;
  const fr_features all_off = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_GLOW |
                              FR_FEATURE_FOG | FR_FEATURE_REFLECTIONS | kStageDepthOfField;
  for (int lanes : {1, 16})
    for (fr_features off :
         {fr_features{0}, fr_features{FR_FEATURE_AO}, fr_features{FR_FEATURE_SHADOWS}, all_off}) {
      settings.lanes = lanes;
      settings.disabled_stages = off;
      expect_sphere_frame(renderer.render(info, state, settings, true), info,
                          "lanes " + std::to_string(lanes) + " off " + std::to_string(off));
    }
  settings.lanes = 16;
  settings.disabled_stages = 0;
  for (auto shading : {ShadingModel::Lambert, ShadingModel::BlinnPhong, ShadingModel::OrenNayar})
    for (bool alternative : {false, true}) {
      settings.shading = shading;
      settings.normals = alternative ? NormalMethod::CentralDifferences : NormalMethod::Tetrahedron;
      settings.ao_method = alternative ? AoMethod::Sampled : AoMethod::StepCount;
      settings.shadow_method = alternative ? ShadowMethod::Hard : ShadowMethod::Soft;
      settings.fog_method = alternative ? FogMethod::PowerLaw : FogMethod::Exponential;
      expect_sphere_frame(renderer.render(info, state, settings, true), info,
                          "shading " + std::to_string(int(shading)) +
                              (alternative ? " alternative modes" : " default modes"));
    }
  const size_t built = test::runtime().programs_built();
  renderer.render(info, state, settings, true);
  EXPECT_EQ(test::runtime().programs_built(), built) << "a repeated frame must come from the cache";
  // A frame that writes fewer passes is another kernel (FR_OUTPUTS), built once as well.
  renderer.render(info, state, settings);
  renderer.render(info, state, settings);
  EXPECT_EQ(test::runtime().programs_built(), built + 1);
}

// A scene that defines a macro named like a built-in the host's stages use (fmax: the march
// takes the larger of two distances with it; PoCL's own header defines it as a macro) renders
// exactly as without it: the scene's macros are restored after its code
// (render/scene_source_guard.hpp).
TEST(KernelAssembly, SceneMacrosDoNotReachTheHostStages) {
  const SceneInfo plain = sphere_scene(FR_FEATURE_AO | FR_FEATURE_SHADOWS);
  SceneInfo hostile = plain;
  hostile.de_source =
      "#define fmax(a, b) (a)\n#define fmin(a, b) (b)\n#undef sqrt\n" + plain.de_source;
  const SceneState state = make_default_state(plain);
  Renderer renderer(test::runtime());
  RenderSettings settings;
  settings.width_px = 32;
  settings.height_px = 24;
  const FrameImage expected = renderer.render(plain, state, settings, true);
  const FrameImage got = renderer.render(hostile, state, settings, true);
  EXPECT_EQ(got.rgba8, expected.rgba8);
  EXPECT_EQ(got.depth, expected.depth);
  expect_sphere_frame(got, hostile, "a scene that defines fmax and fmin");
}

}  // namespace
}  // namespace fr
