// The cone pre-pass (kernels/cone.cl) only skips empty space: with it, every primary ray finds
// the same surface as without it, for every in-tree scene, at a far camera (rays on the start
// plane), at a tight bounding sphere (Julia with c = 0: the unit ball inside radius ~1.05) and in a
// window of a larger image (a poster's band, whose blocks lie on the whole image's grid).
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <cmath>

namespace fr {
namespace {

struct View {
  std::shared_ptr<const LoadedScene> scene;
  SceneState state;
};

View scene_view(const std::string& id) {
  View v;
  v.scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  v.state = make_default_state(v.scene->info);
  std::string error;
  auto instance = SceneInstance::create(v.scene, &error);
  EXPECT_TRUE(instance && instance->update(v.state, 0.0, &error)) << error;
  return v;
}

// Renders with and without the pre-pass and compares the primary rays: the same pixels hit (but
// for a few along silhouettes, where the march's stop point decides), and hardly any found further
// away than a few hit thresholds (which a skipped surface would be).
void expect_same_surface(const View& v, RenderSettings s, const std::string& what) {
  s.precision = Precision::Float;
  // Plain sphere tracing: a relaxed step may jump a thin feature or not depending on where the
  // ray started, which is relaxation's risk (march.cl guards it), not the cone's.
  s.relaxation = 1;
  s.count_evaluations = true;
  s.cone_prepass = false;
  Renderer renderer(test::runtime());
  const FrameImage off = renderer.render(v.scene->info, v.state, s, true);
  const EvalCounts off_counts = renderer.eval_counts();
  s.cone_prepass = true;
  const FrameImage on = renderer.render(v.scene->info, v.state, s, true);
  const EvalCounts on_counts = renderer.eval_counts();

  const double pixel_angle =
      make_camera_rays(v.state.camera,
                       s.window.full_width_px > 0 ? s.window.full_width_px : s.width_px,
                       s.window.full_height_px > 0 ? s.window.full_height_px : s.height_px)
          .pixel_angle_rad;
  size_t both = 0, differ = 0, further = 0;
  for (size_t i = 0; i < on.depth.size(); ++i) {
    const bool hit_on = std::isfinite(on.depth[i]), hit_off = std::isfinite(off.depth[i]);
    if (hit_on != hit_off) {
      ++differ;
      continue;
    }
    if (!hit_on) continue;
    ++both;
    // Both stop within a few thresholds (k * t * pixel angle) of the surface they reached.
    const double eps = s.hit_threshold_k * off.depth[i] * pixel_angle;
    if (on.depth[i] > off.depth[i] + 8 * eps + 1e-5 * off.depth[i]) {
      ++further;
      std::printf("%s: pixel %zu,%zu depth %.6g with the cone, %.6g without\n", what.c_str(),
                  i % s.width_px, i / s.width_px, on.depth[i], off.depth[i]);
    }
  }
  EXPECT_GT(both, on.depth.size() / 20) << what;
  EXPECT_LE(differ, on.depth.size() / 200) << what << ": hit in one, missed in the other";
  // A ray grazing a surface at about the hit threshold hits or passes by depending on where its
  // steps land, with or without the cone (the same ambiguity as at a silhouette): a few such
  // pixels, never the blocks of 8x8 that a cone skipping a surface would leave.
  EXPECT_LE(further, std::max<size_t>(2, on.depth.size() / 500))
      << what << ": rays that went past the surface they hit without the cone";
  auto march_evals = [](const EvalCounts& c) {
    double sum = 0;
    for (const auto& r : stage_counts(c))
      if (r.bounce == 0 && (r.stage == "march" || r.stage == "cone pre-pass"))
        sum += r.evals_per_pixel;
    return sum;
  };
  std::printf("%s: march %.3f evaluations per pixel without the cone, %.3f with it\n", what.c_str(),
              march_evals(off_counts), march_evals(on_counts));
}

RenderSettings small() {
  RenderSettings s;
  s.width_px = 96;
  s.height_px = 54;
  return s;
}

class EveryScene : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryScene, SameSurfaceWithTheCone) {
  expect_same_surface(scene_view(GetParam()), small(), GetParam());
}

TEST_P(EveryScene, SameSurfaceFromFarAway) {
  View v = scene_view(GetParam());
  // 1000 bounding radii back along the view, with a narrow field to keep the scene in frame.
  for (int a = 0; a < 3; ++a)
    v.state.camera.eye[a] =
        v.state.camera.target[a] + (v.state.camera.eye[a] - v.state.camera.target[a]) * 1000.0;
  v.state.camera.fov_deg /= 1000.0;
  expect_same_surface(v, small(), std::string(GetParam()) + " from 1000x further");
}

TEST_P(EveryScene, SameSurfaceInAWindowOffTheBlockGrid) {
  RenderSettings s = small();
  s.window = {160, 90, 13, 21};  // 96x54 pixels of a 160x90 image, 13 and 21 pixels in
  expect_same_surface(scene_view(GetParam()), s, std::string(GetParam()) + " window");
}

INSTANTIATE_TEST_SUITE_P(InTreeScenes, EveryScene,
                         ::testing::Values("mandelbulb", "menger", "sierpinski", "julia",
                                           "benchmark"));

// The unit ball just inside a bounding sphere of radius ~1.05: rays next to the block's centre ray
// enter the bounds before it does, and the cone must not start where the centre ray enters.
TEST(ConePrepass, TightBoundsKeepTheSphere) {
  View v = scene_view("julia");
  v.state.params[v.scene->info.find_param("c")] = fr_value{{0, 0, 0}};
  v.state.params[v.scene->info.find_param("c_w")] = fr_value{{0, 0, 0}};
  v.state.params[v.scene->info.find_param("slice_w")] = fr_value{{0, 0, 0}};
  std::string error;
  auto instance = SceneInstance::create(v.scene, &error);
  ASSERT_TRUE(instance && instance->update(v.state, 0, &error)) << error;
  ASSERT_LE(v.state.bounding_radius, 1.1);
  v.state.camera.eye[0] = 0.4;
  v.state.camera.eye[1] = 0.9;
  v.state.camera.eye[2] = 3.2;
  v.state.camera.target[0] = v.state.camera.target[1] = v.state.camera.target[2] = 0;
  expect_same_surface(v, small(), "unit ball in tight bounds");
}

}  // namespace
}  // namespace fr
