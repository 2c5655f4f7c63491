// A click focuses the thin lens on the surface under the pointer (issue 36's explorer point),
// against exact geometry: the unit ball seen from outside, the focus distance along the view the
// ray-sphere intersection gives in double; the sky leaves the focus where it was.
#include "app/explorer.hpp"
#include "render/camera.hpp"
#include "test_paths.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace fr {
namespace {

TEST(ExplorerFocus, AClickFocusesOnTheSurfaceUnderThePointer) {
  const auto dir = test::folder_of_one_scene("focus_plugins", TEST_SCENE_DIR, "unit_ball");
  std::vector<SceneEvent> events;
  SceneLibrary library({dir}, PluginPolicy{}, RenderSettings{}, test::worker(), &events);
  ASSERT_EQ(library.slots().size(), 1u);
  Settings settings;
  settings.render.aperture_radius = 0.05f;
  Explorer explorer(settings, test::worker(), library, "unit_ball");
  fr_camera& camera = explorer.current().state.camera;
  camera.eye[0] = 0.3;
  camera.eye[1] = 0.2;
  camera.eye[2] = 3.5;
  camera.target[0] = camera.target[1] = camera.target[2] = 0;
  const int w = 64, h = 48;
  const CameraRays rays = make_camera_rays(camera, w, h);
  const glm::dvec3 eye(camera.eye[0], camera.eye[1], camera.eye[2]);
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{32, 24}, {20, 30}, {40, 15}}) {
    SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
    // |eye + t d| = 1: t^2 + 2 (eye . d) t + |eye|^2 - 1 = 0, the nearer root.
    const glm::dvec3 d = camera_ray_dir(rays, x, y);
    const double b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1;
    ASSERT_GT(b * b - c, 0) << "the pixel sees the ball";
    const double t = -b - std::sqrt(b * b - c);
    const double expected = t * glm::dot(d, rays.forward);
    const auto focus = explorer.focus_at(x, y, w, h);
    ASSERT_TRUE(focus.has_value());
    // Closer than a quarter of a frame's hit threshold there (k t times the pixel angle): a
    // frame's own rays stop that far before the surface, the focus's ray nearer.
    const double frame_threshold = RenderSettings{}.hit_threshold_k * t * rays.pixel_angle_rad;
    EXPECT_NEAR(*focus, expected, 0.25 * frame_threshold);
    EXPECT_FLOAT_EQ(explorer.render_settings().focus_distance, static_cast<float>(*focus));
  }
  // A corner sees the sky: nothing to focus on, the focus stays.
  const float before = explorer.render_settings().focus_distance;
  EXPECT_FALSE(explorer.focus_at(0, 0, w, h).has_value());
  EXPECT_EQ(explorer.render_settings().focus_distance, before);
  // Outside the window: nothing.
  EXPECT_FALSE(explorer.focus_at(w, 0, w, h).has_value());
  EXPECT_FALSE(explorer.focus_at(-1, 3, w, h).has_value());
  // Through the input: a click's pixel is focused at the next render.
  InputState input;
  apply_input_event(KeyBindings::defaults(),
                    InputEvent{InputEvent::Type::MouseClick, "", 0, 0, 32, 24, 0, 0}, input);
  ASSERT_TRUE(input.clicked.has_value());
  explorer.render_settings().focus_distance = 7;
  explorer.update(input, 1.0 / 30, 0);
  ASSERT_NE(explorer.render(w, h), nullptr);
  EXPECT_NEAR(explorer.render_settings().focus_distance, 2.55, 0.1) << "the ball's front";
  input.end_frame();
  EXPECT_FALSE(input.clicked.has_value()) << "a click lasts one frame";
}

}  // namespace
}  // namespace fr
