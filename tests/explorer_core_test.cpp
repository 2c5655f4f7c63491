// The explorer's parts without a window: input mapping, the camera controller, the frame-time
// controller on a fake clock, the loop's order, and carrying parameters across a reload.
#include "app/camera_controller.hpp"
#include "app/frame_controller.hpp"
#include "app/game_loop.hpp"
#include "app/input.hpp"
#include "app/scene_slot.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace fr {
namespace {

InputEvent key(const char* name, bool down = true) {
  InputEvent e;
  e.type = down ? InputEvent::Type::KeyDown : InputEvent::Type::KeyUp;
  e.key = name;
  return e;
}

TEST(Input, BindingsMapKeysToActions) {
  const KeyBindings b = KeyBindings::defaults();
  InputState s;
  apply_input_event(b, key("W"), s);
  apply_input_event(b, key("Left Shift"), s);
  apply_input_event(b, key("Tab"), s);
  apply_input_event(b, key("Unbound Key"), s);
  EXPECT_TRUE(s.is_held(Action::MoveForward));
  EXPECT_TRUE(s.is_held(Action::SpeedUp));
  EXPECT_TRUE(s.was_triggered(Action::NextScene));
  EXPECT_FALSE(s.is_held(Action::NextScene)) << "one-shot actions are not held";
  s.end_frame();
  EXPECT_FALSE(s.was_triggered(Action::NextScene)) << "triggers last one frame";
  EXPECT_TRUE(s.is_held(Action::MoveForward)) << "held keys stay held";
  apply_input_event(b, key("W", false), s);
  EXPECT_FALSE(s.is_held(Action::MoveForward));
  apply_input_event(b, key("Escape"), s);
  EXPECT_TRUE(s.quit);
  EXPECT_EQ(b.keys_for(Action::MoveUp), (std::vector<std::string>{"E", "Space"}));
  EXPECT_EQ(action_from_name("move_forward"), Action::MoveForward);
  EXPECT_FALSE(action_from_name("fly_to_moon").has_value());
}

fr_camera looking_down_minus_z() {
  fr_camera c{};
  c.struct_size = sizeof c;
  c.eye[2] = 10;
  c.up[1] = 1;
  c.fov_deg = 45;
  return c;
}

// Labels (the overlay's "(O)", "Fractalis (F1 hides)") name the keys in force: [controls.keys]
// adds keys over the defaults.
TEST(Input, LabelsNameTheKeysInForce) {
  const KeyBindings defaults = KeyBindings::defaults();
  EXPECT_EQ(defaults.label(Action::ToggleCameraMode), "O");
  EXPECT_EQ(defaults.label(Action::MoveUp), "E/Space");
  const KeyBindings extra =
      KeyBindings::with_extra({{"G", "camera_mode"}, {"H", "no_such_action"}});
  EXPECT_EQ(extra.label(Action::ToggleCameraMode), "G/O");
  EXPECT_EQ(extra.keys.count("H"), 0u)
      << "an unknown action (reported by the settings) binds nothing";
  EXPECT_EQ(KeyBindings{}.label(Action::Quit), "unbound");
}

// README's key table lists exactly the default bindings: every default key is in it, and it
// names no key that is not one (the words between keys are only "or" and "(held)").
TEST(Input, ReadmeKeyTableIsTheDefaultBindings) {
  std::ifstream readme(std::string(SOURCE_DIR) + "/README.md");
  std::string line, first_column;
  bool in_table = false;
  while (std::getline(readme, line)) {
    if (line.rfind("| key / mouse | does |", 0) == 0) {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    if (line.empty() || line[0] != '|') break;
    if (line.rfind("| ---", 0) == 0) continue;
    first_column += " " + line.substr(1, line.find('|', 1) - 1) + " ";
  }
  ASSERT_FALSE(first_column.empty()) << "README has no key table";
  std::vector<std::string> keys;
  for (const auto& [key, action] : KeyBindings::defaults().keys) keys.push_back(key);
  // Longest first, so that "Left Shift" goes before a "Shift" could.
  std::sort(keys.begin(), keys.end(),
            [](const auto& a, const auto& b) { return a.size() > b.size(); });
  auto is_word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
  std::string rest = first_column;
  for (const std::string& key : keys) {
    bool found = false;
    for (size_t at = rest.find(key); at != std::string::npos; at = rest.find(key, at + 1)) {
      const bool starts = at == 0 || !is_word_char(rest[at - 1]);
      const bool ends = at + key.size() == rest.size() || !is_word_char(rest[at + key.size()]);
      if (starts && ends) {
        // Blanked in place (std::string::replace with a shorter text trips GCC 12's -Wrestrict).
        std::fill(rest.begin() + static_cast<std::ptrdiff_t>(at),
                  rest.begin() + static_cast<std::ptrdiff_t>(at + key.size()), ' ');
        found = true;
      }
    }
    EXPECT_TRUE(found) << "README's key table lacks the default key " << key;
  }
  std::istringstream words(rest);
  for (std::string word; words >> word;) {
    while (!word.empty() && (word.back() == ',' || word.back() == '/')) word.pop_back();
    if (word.empty() || word == "or" || word == "(held)") continue;
    ADD_FAILURE() << "README's key table names '" << word << "', which is no default key";
  }
}

TEST(CameraController, FlySpeedFollowsTheSurfaceDistance) {
  InputState in;
  in.held.insert(Action::MoveForward);
  CameraControls controls;
  fr_camera far = looking_down_minus_z(), near = looking_down_minus_z();
  // 0.1 s at speed = 1 x distance: 0.5 units at distance 5, 0.001 at distance 0.01.
  EXPECT_TRUE(update_camera(far, CameraMode::Fly, in, false, 0.1, 5.0, controls).moved);
  update_camera(near, CameraMode::Fly, in, false, 0.1, 0.01, controls);
  EXPECT_NEAR(far.eye[2], 10 - 0.5, 1e-12);
  EXPECT_NEAR(near.eye[2], 10 - 0.001, 1e-12);
  EXPECT_NEAR(far.target[2] - far.eye[2], -10, 1e-12) << "the target moves with the eye";
}

TEST(CameraController, NeverStepsThroughTheSurface) {
  InputState in;
  in.held.insert(Action::MoveForward);
  in.held.insert(Action::SpeedUp);
  CameraControls controls;
  controls.speed_per_distance = 100;  // absurdly fast
  fr_camera c = looking_down_minus_z();
  update_camera(c, CameraMode::Fly, in, false, 1.0, 2.0, controls);
  // Speed 100 x 2 x 4 = 800 clamps to max_speed 10, i.e. 10 units this second; the step is then
  // cut to 0.9 of the surface distance 2: exactly 1.8 (a camera that did not move, or moved
  // the full 10, fails).
  EXPECT_NEAR(c.eye[2], 10 - 0.9 * 2.0, 1e-12);
  EXPECT_EQ(c.eye[0], 0);
  EXPECT_EQ(c.eye[1], 0);
  // Far from any surface the clamp on speed is what limits the step: 10 units per second.
  fr_camera free = looking_down_minus_z();
  update_camera(free, CameraMode::Fly, in, false, 0.5, 1000.0, controls);
  EXPECT_NEAR(free.eye[2], 10 - 0.5 * controls.max_speed, 1e-12);
}

TEST(CameraController, MouseLookYawsAndInvertY) {
  InputState in;
  in.look_dx = 100;  // 100 px at 0.15 deg/px: 15 degrees to the right
  CameraControls controls;
  fr_camera c = looking_down_minus_z();
  update_camera(c, CameraMode::Fly, in, true, 0.016, 1.0, controls);
  const glm::dvec3 forward = glm::normalize(
      glm::dvec3(c.target[0] - c.eye[0], c.target[1] - c.eye[1], c.target[2] - c.eye[2]));
  EXPECT_NEAR(forward.x, std::sin(15 * std::numbers::pi / 180), 1e-9);
  EXPECT_NEAR(forward.z, -std::cos(15 * std::numbers::pi / 180), 1e-9);
  // Without mouse look the mouse does nothing.
  fr_camera still = looking_down_minus_z();
  EXPECT_FALSE(update_camera(still, CameraMode::Fly, in, false, 0.016, 1.0, controls).moved);
  // Moving the mouse up looks up, or down with invert_y.
  InputState up;
  up.look_dy = -100;
  fr_camera a = looking_down_minus_z(), b = looking_down_minus_z();
  update_camera(a, CameraMode::Fly, up, true, 0.016, 1.0, controls);
  controls.invert_y = true;
  update_camera(b, CameraMode::Fly, up, true, 0.016, 1.0, controls);
  EXPECT_GT(a.target[1], 0);
  EXPECT_LT(b.target[1], 0);
}

// At a pole (up +z, looking down -z, as --eye 0,0,10 --target 0,0,0 --up 0,0,1 gives) the
// controls use the image's stable up (+y): strafing right moves along the image's right, +x
// (camera_test derives it), and looking around never makes the camera non-finite.
TEST(CameraController, WorksAtAPole) {
  fr_camera c = looking_down_minus_z();
  c.up[1] = 0;
  c.up[2] = 1;
  InputState right;
  right.held.insert(Action::MoveRight);
  CameraControls controls;
  update_camera(c, CameraMode::Fly, right, false, 1.0, 1.0, controls);
  EXPECT_GT(c.eye[0], 0);
  EXPECT_NEAR(c.eye[1], 0, 1e-12);
  EXPECT_NEAR(c.eye[2], 10, 1e-12);
  InputState look;
  look.look_dx = 40;
  look.look_dy = 300;
  for (int i = 0; i < 10; ++i) update_camera(c, CameraMode::Fly, look, true, 0.016, 1.0, controls);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(std::isfinite(c.eye[i]) && std::isfinite(c.target[i]));
  }
  EXPECT_FALSE(check_camera(c).has_value());
}

TEST(CameraController, OrbitKeepsTheTarget) {
  InputState in;
  in.look_dx = 600;  // 90 degrees around
  CameraControls controls;
  fr_camera c = looking_down_minus_z();
  update_camera(c, CameraMode::Orbit, in, true, 0.016, 5.0, controls);
  EXPECT_NEAR(c.target[0], 0, 1e-12);
  EXPECT_NEAR(c.target[2], 0, 1e-12);
  EXPECT_NEAR(std::hypot(c.eye[0], c.eye[2]), 10, 1e-9);
  EXPECT_NEAR(std::abs(c.eye[0]), 10, 1e-9);
}

// On a fake clock: frames slower than the target shrink the scale until they meet it; once still,
// the controller goes to full resolution and counts samples up to full quality, then stops.
TEST(FrameController, HoldsTheTargetThenRefines) {
  FrameControllerSettings s;
  s.target_frame_ms = 40;
  s.full_quality_samples = 4;
  FrameController fc(s);
  double scale = fc.scale();
  for (int i = 0; i < 10; ++i) {
    const FramePlan p = fc.plan(true);
    EXPECT_EQ(p.sample_index, 0);
    EXPECT_LT(p.step_budget, 1) << "a reduced step budget while moving";
    // Render time proportional to pixels: 320 ms at full scale.
    fc.report(320 * p.resolution_scale * p.resolution_scale);
  }
  EXPECT_LT(fc.scale(), scale);
  EXPECT_NEAR(fc.scale(), std::sqrt(40.0 / 320), 0.02) << "320 ms x scale^2 = 40 ms, the target";
  for (int i = 0; i < 4; ++i) {
    const FramePlan p = fc.plan(false);
    EXPECT_EQ(p.resolution_scale, 1);
    EXPECT_EQ(p.step_budget, 1);
    EXPECT_EQ(p.sample_index, i);
    EXPECT_FALSE(p.done);
  }
  EXPECT_TRUE(fc.plan(false).done);
  EXPECT_EQ(fc.plan(true).sample_index, 0) << "a change restarts";
}

// With temporal reuse the controller picks the lattice instead of the scale: the largest share
// of traced pixels whose time (proportional to it here) meets the target.
TEST(FrameController, PicksTheLatticeThatHoldsTheTarget) {
  FrameControllerSettings s;
  s.target_frame_ms = 40;
  FrameController fc(s);
  FramePlan p;
  for (int i = 0; i < 40; ++i) {
    p = fc.plan(true, /*reuse=*/true);
    ASSERT_TRUE(p.lattice);
    EXPECT_EQ(p.resolution_scale, 1) << "full resolution: a lattice of the window's pixels";
    EXPECT_LE(std::abs(p.stride_x - p.stride_y), 1);
    // 360 ms for every pixel: 1 in 9 meets 40 ms, 1 in 6 (60 ms) does not.
    fc.report(360.0 / (p.stride_x * p.stride_y));
  }
  EXPECT_EQ(p.stride_x * p.stride_y, 9) << p.stride_x << "x" << p.stride_y;
  for (int i = 0; i < 40; ++i) {
    p = fc.plan(true, true);
    fc.report(2.0);  // a cheap view: every pixel, every frame
  }
  EXPECT_EQ(p.stride_x * p.stride_y, 1);
  for (int i = 0; i < 40; ++i) {
    p = fc.plan(true, true);
    fc.report(10000.0);  // never fast enough: the coarsest lattice, no coarser
  }
  EXPECT_EQ(p.stride_x, s.max_stride);
  EXPECT_EQ(p.stride_y, s.max_stride);
  // Reuse not possible this frame (more than the camera changed): scaled, as without it.
  p = fc.plan(true, false);
  EXPECT_FALSE(p.lattice);
  EXPECT_LT(p.resolution_scale, 1);
}

TEST(GameLoop, PollUpdateRenderInOrderOnAFakeClock) {
  std::vector<std::string> order;
  double clock = 100;
  std::vector<double> dts;
  int polls = 0;
  LoopSteps steps;
  steps.now_s = [&] { return clock; };
  steps.poll = [&](InputState& in) {
    order.push_back("poll");
    if (++polls == 4) in.quit = true;
  };
  steps.update = [&](const InputState&, double dt) {
    order.push_back("update");
    dts.push_back(dt);
  };
  steps.render = [&] {
    order.push_back("render");
    clock += 0.025;
    return true;
  };
  EXPECT_EQ(run_game_loop(steps), 3);
  EXPECT_EQ(order, (std::vector<std::string>{"poll", "update", "render", "poll", "update", "render",
                                             "poll", "update", "render", "poll"}));
  ASSERT_EQ(dts.size(), 3u);
  EXPECT_DOUBLE_EQ(dts[0], 0);
  EXPECT_NEAR(dts[1], 0.025, 1e-12);
  EXPECT_NEAR(dts[2], 0.025, 1e-12);
}

// max_frames counts the frames the window showed, not the turns of the loop: a script that asks
// for 5 frames gets 5 of the scene even when the first turns only said it was being prepared.
TEST(GameLoop, MaxFramesCountsFramesShown) {
  int turns = 0;
  LoopSteps steps;
  steps.now_s = [] { return 0.0; };
  steps.poll = [](InputState&) {};
  steps.update = [](const InputState&, double) {};
  steps.render = [&] { return ++turns > 3; };  // three notices, then frames
  EXPECT_EQ(run_game_loop(steps, 5), 5);
  EXPECT_EQ(turns, 8);
}

TEST(Reload, ParametersCarryOverByKey) {
  auto param = [](const char* key, fr_param_type type, double def, double lo, double hi) {
    ParamInfo p;
    p.key = key;
    p.type = type;
    p.default_value.v[0] = def;
    p.min_value.v[0] = lo;
    p.max_value.v[0] = hi;
    return p;
  };
  SceneInfo old_info, new_info;
  old_info.params = {param("power", FR_PARAM_FLOAT, 8, 2, 16), param("gone", FR_PARAM_INT, 1, 0, 9),
                     param("bailout", FR_PARAM_FLOAT, 2, 1, 64)};
  new_info.params = {param("bailout", FR_PARAM_FLOAT, 2, 1, 12),
                     param("fresh", FR_PARAM_FLOAT, 0.5, 0, 1),
                     param("power", FR_PARAM_FLOAT, 8, 2, 16)};
  const std::vector<fr_value> old_values = {{{11, 0, 0}}, {{7, 0, 0}}, {{40, 0, 0}}};
  const auto v = rebind_params(old_info, old_values, new_info);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].v[0], 12) << "out of the new range: clamped";
  EXPECT_EQ(v[1].v[0], 0.5) << "new key: its default";
  EXPECT_EQ(v[2].v[0], 11) << "same key: kept";
}

}  // namespace
}  // namespace fr

namespace fr {
namespace {

// The wheel zooms towards the surface under the pointer, in pairs: 400 notches (a quarter of the
// way each) from 1 away reach some 1e-50 of it in exact arithmetic, and the camera stops where a
// pair stops telling points apart (2^-100 of the eye's size), never on or past the point; the
// view keeps its direction, and the point stays on the pointer's ray.
TEST(CameraController, WheelZoomsPastDoubleInPairs) {
  fr_camera c{};
  c.struct_size = sizeof c;
  c.eye[0] = 1.3;
  c.eye[1] = 0.2;
  c.target[0] = -1.7;  // looking along -x, 3 away
  c.target[1] = 0.2;
  c.up[2] = 1;
  c.fov_deg = 60;
  CameraLow low;
  // The surface point 1 along a ray a little off the view: (0.3, 0.2 + 0.01, 0) from the eye's
  // (1.3, 0.2, 0), unnormalised direction (-1, 0.01, 0).
  ZoomPoint point;
  const double length = std::sqrt(1 + 1e-4);
  point.dir[0] = -1 / length;
  point.dir[1] = 0.01 / length;
  point.distance = length;
  InputState in;
  in.wheel = 1;
  CameraControls controls;
  // How far the eye is from the point (0.3, 0.21, 0) along x, as __float128 sees the pair.
  const auto offset_x = [&] {
    return static_cast<double>((__float128)c.eye[0] + low.eye[0] - (__float128)0.3);
  };
  const double offset0 = offset_x();  // 1, and what 1.3 and 0.3 lack of their doubles
  for (int i = 0; i < 400; ++i) {
    update_camera(c, low, CameraMode::Fly, in, false, 0.016, 1e9, controls, &point);
    // What the explorer measures next: the distance to the point along the ray.
    point.distance = offset_x() * length;
    const double expected = std::pow(0.75, i + 1) * offset0;
    if (i == 100 || i == 160) {  // 2.4e-13 (double still holds it), 7.7e-21 (past double)
      EXPECT_NEAR(offset_x(), expected, 1e-9 * expected) << "after " << i + 1 << " notches";
    }
  }
  EXPECT_GT(offset_x(), 0) << "the zoom went onto or past the point";
  EXPECT_LT(offset_x(), 1e-28) << "the zoom stopped short of a pair's resolution";
  // The view's direction is what it was (-x), at any depth.
  const std::array<double, 3> view = view_vector(c, low);
  EXPECT_NEAR(view[0] / 3, -1, 1e-12);
  EXPECT_NEAR(view[1], 0, 1e-12);
}

}  // namespace
}  // namespace fr
