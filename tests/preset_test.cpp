// A scene's state written as a preset (format_preset: a screenshot's saved view) and read back:
// every parameter type to the same value, and a deep view's eye and target to the same pairs,
// with the digits they were given (as many as a pair holds).
#include "io/dd_text.hpp"
#include "path/preset.hpp"
#include "plugin/scene_instance.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace fr {
namespace {

SceneInfo every_type_scene() {
  SceneInfo info;
  info.id = "every_type";
  info.name = "Every \"type\"";
  const auto add = [&](const char* key, fr_param_type type, double lo, double def, double hi) {
    ParamInfo p;
    p.key = key;
    p.name = key;
    p.type = type;
    for (int c = 0; c < 3; ++c) {
      p.min_value.v[c] = lo;
      p.default_value.v[c] = def;
      p.max_value.v[c] = hi;
    }
    if (type != FR_PARAM_VEC3 && type != FR_PARAM_COLOR)
      for (int c = 1; c < 3; ++c) p.min_value.v[c] = p.default_value.v[c] = p.max_value.v[c] = 0;
    info.params.push_back(p);
  };
  add("scale", FR_PARAM_FLOAT, -3, 2, 3);
  add("iterations", FR_PARAM_INT, 1, 14, 100);
  add("julia", FR_PARAM_BOOL, 0, 0, 1);
  add("c", FR_PARAM_VEC3, -4, 1.8, 4);
  add("kind", FR_PARAM_CHOICE, 0, 0, 2);
  info.params.back().choices = {"box", "bulb", "sponge"};
  info.camera = fr_camera{sizeof(fr_camera), 0, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 45};
  info.bounding_radius = 12;
  return info;
}

TEST(PresetFormat, RoundTripsEveryValueAndADeepView) {
  const SceneInfo info = every_type_scene();
  SceneState state = make_default_state(info);
  state.params[0].v[0] = -1.2345678901234567;  // needs all 17 digits
  state.params[1].v[0] = 77;
  state.params[2].v[0] = 1;
  state.params[3] = {{0.1, -2.5e-7, 3.999999999999999}};
  state.params[4].v[0] = 2;
  // A view 1e-20 deep: the eye and target apart only in their digits past double.
  const char* eye_text[3] = {"5.908838584519028311185277143352341",
                             "5.365192127899789404866847363500787",
                             "4.061601182686364386385179208868661"};
  const char* target_text[3] = {"5.908838584519028311179323496609206",
                                "5.365192127899789404860655570887927",
                                "4.061601182686364386380059072669565"};
  for (int c = 0; c < 3; ++c) {
    const auto eye = parse_double_double(eye_text[c]);
    const auto target = parse_double_double(target_text[c]);
    ASSERT_TRUE(eye && target);
    state.camera.eye[c] = eye->hi;
    state.camera_lo.eye[c] = eye->lo;
    state.camera.target[c] = target->hi;
    state.camera_lo.target[c] = target->lo;
  }
  state.camera.fov_deg = 0.1 + 0.2;  // 0.30000000000000004

  const std::string text = format_preset(info, state, "A \"deep\" view", "Saved by a test.");
  // The digits given, as far as a pair holds them (about 32 significant; 34 are written).
  for (const char* digits : eye_text)
    EXPECT_NE(text.find(std::string(digits, 32)), std::string::npos)
        << "the eye's digits, as given:\n" << text;

  std::vector<std::string> problems;
  const auto preset = preset_from_text(text, "view.toml", "view", &problems);
  ASSERT_TRUE(preset) << (problems.empty() ? text : problems.front());
  EXPECT_EQ(preset->name, "A \"deep\" view");
  SceneState back = make_default_state(info);
  const auto apply_problems = apply_preset(*preset, info, back);
  ASSERT_TRUE(apply_problems.empty()) << apply_problems.front();
  for (size_t i = 0; i < state.params.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(back.params[i].v[c], state.params[i].v[c]) << info.params[i].key << "[" << c << "]";
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(back.camera.eye[c], state.camera.eye[c]);
    EXPECT_EQ(back.camera_lo.eye[c], state.camera_lo.eye[c]);
    EXPECT_EQ(back.camera.target[c], state.camera.target[c]);
    EXPECT_EQ(back.camera_lo.target[c], state.camera_lo.target[c]);
    EXPECT_EQ(back.camera.up[c], state.camera.up[c]);
  }
  EXPECT_EQ(back.camera.fov_deg, state.camera.fov_deg);
}

}  // namespace
}  // namespace fr
