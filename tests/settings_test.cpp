// The settings loader's errors: file, line, key and what was expected; unknown keys named with
// the nearest known key; good values still apply when another is wrong.
#include "settings/settings.hpp"
#include "test_support.hpp"

#include <fstream>
#include <sstream>

namespace fr {
namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  auto path = std::filesystem::path(TEST_OUTPUT_DIR) / name;
  std::ofstream(path) << text;
  return path;
}

TEST(Settings, GoodFileApplies) {
  Settings s;
  auto file =
      write_file("good.toml",
                 "[plugins]\nfolders = [\"/tmp/a\", \"/tmp/b\"]\n[device]\nselect = \"cpu\"\n"
                 "[render]\nlanes = 8\nprecision = \"double\"\n[render.effects]\nao = false\n");
  auto problems = load_settings_file(file, s);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  ASSERT_EQ(s.plugin_folders.size(), 2u);
  EXPECT_EQ(s.plugin_folders[1], "/tmp/b");
  EXPECT_EQ(s.device, "cpu");
  EXPECT_EQ(s.render.lanes, 8);
  EXPECT_EQ(s.render.precision, Precision::Double);
  EXPECT_EQ(s.render.disabled_stages, FR_FEATURE_AO);
}

TEST(Settings, BadTomlNamesFileAndLine) {
  Settings s;
  auto file = write_file("bad_syntax.toml", "[render]\nlanes = 16\nprecision = \"float\n");
  auto problems = load_settings_file(file, s);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].line, 3);
  EXPECT_NE(problems[0].to_string().find("bad_syntax.toml:3:"), std::string::npos)
      << problems[0].to_string();
}

// Deep nesting overflows the TOML parser's recursion: refused before parsing, with the line, for
// a file and for --set alike (both would crash the process otherwise).
TEST(Settings, DeeplyNestedTomlIsRefusedNotParsed) {
  const auto dir = test::fresh_dir("deep_toml");
  const auto file = dir / "deep.toml";
  std::ofstream(file) << "[render]\nsamples = 2\nx = " << std::string(100000, '[') << "\n";
  Settings s;
  auto problems = load_settings_file(file, s);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].line, 3);
  EXPECT_NE(problems[0].message.find("nested more than 64 levels deep"), std::string::npos)
      << problems[0].message;
  std::string dotted = "render";
  for (int i = 0; i < 50000; ++i) dotted += ".a";
  problems = apply_setting_override(dotted + "=1", s);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("nested more than 64 levels deep"), std::string::npos);
  // Dots in numbers and strings do not count.
  EXPECT_TRUE(apply_setting_override("render.exposure=1.25", s).empty());
  EXPECT_TRUE(apply_setting_override(
                  "device.select=\"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.a.b.c.d.e.f."
                  "g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.a.b.c.d.e.f.g.h\"",
                  s)
                  .empty());
}

TEST(Settings, WrongTypeAndRangeKeepDefaults) {
  Settings s;
  auto file = write_file("wrong_type.toml",
                         "[render]\nlanes = \"sixteen\"\nmax_steps = -4\nexposure = 2.0\n");
  auto problems = load_settings_file(file, s);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].key, "render.lanes");
  EXPECT_EQ(problems[0].line, 2);
  EXPECT_NE(problems[0].message.find("1, 4, 8, 16"), std::string::npos);
  EXPECT_EQ(problems[1].key, "render.max_steps");
  EXPECT_EQ(problems[1].line, 3);
  EXPECT_EQ(s.render.lanes, RenderSettings{}.lanes);
  EXPECT_EQ(s.render.max_steps, RenderSettings{}.max_steps);
  EXPECT_EQ(s.render.exposure, 2.0f) << "the good value still applies";
}

TEST(Settings, UnknownKeyNamesNearest) {
  Settings s;
  auto file = write_file("typo.toml", "[render]\nlanse = 16\n[plugin]\nfolders = []\n");
  auto problems = load_settings_file(file, s);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].key, "render.lanse");
  EXPECT_NE(problems[0].message.find("did you mean 'render.lanes'"), std::string::npos)
      << problems[0].message;
  EXPECT_EQ(problems[0].line, 2);
  EXPECT_EQ(problems[1].key, "plugin");
  EXPECT_NE(problems[1].message.find("plugins.folders"), std::string::npos) << problems[1].message;
}

}  // namespace
}  // namespace fr

namespace fr {
namespace {

// config/default.toml documents the built-in defaults: it must load cleanly and say the same.
TEST(Settings, DefaultFileMatchesBuiltInDefaults) {
  Settings from_file;
  const auto problems =
      load_settings_file(std::filesystem::path(SOURCE_DIR) / "config" / "default.toml", from_file);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  const Settings builtin;
  EXPECT_EQ(from_file.plugin_folders, builtin.plugin_folders);
  EXPECT_EQ(from_file.device, builtin.device);
  EXPECT_EQ(from_file.render.lanes, builtin.render.lanes);
  EXPECT_EQ(from_file.render.precision, builtin.render.precision);
  EXPECT_EQ(from_file.render.max_steps, builtin.render.max_steps);
  EXPECT_EQ(from_file.render.hit_threshold_k, builtin.render.hit_threshold_k);
  EXPECT_EQ(from_file.render.exposure, builtin.render.exposure);
  EXPECT_EQ(from_file.render.ao_strength, builtin.render.ao_strength);
  EXPECT_EQ(from_file.render.disabled_stages, builtin.render.disabled_stages);
  EXPECT_EQ(from_file.render.samples, builtin.render.samples);
  EXPECT_EQ(from_file.render.relaxation, builtin.render.relaxation);
  EXPECT_EQ(from_file.render.max_bounces, builtin.render.max_bounces);
  EXPECT_EQ(from_file.render.roughness, builtin.render.roughness);
  EXPECT_EQ(from_file.render.reflectivity, builtin.render.reflectivity);
  EXPECT_EQ(from_file.render.aperture_radius, builtin.render.aperture_radius);
  EXPECT_EQ(from_file.render.focus_distance, builtin.render.focus_distance);
  EXPECT_EQ(from_file.render.shading, builtin.render.shading);
  EXPECT_EQ(from_file.render.normals, builtin.render.normals);
  EXPECT_EQ(from_file.render.ao_method, builtin.render.ao_method);
  EXPECT_EQ(from_file.render.shadow_method, builtin.render.shadow_method);
  EXPECT_EQ(from_file.render.fog_method, builtin.render.fog_method);
  // And it names every key the loader knows, so the file documents them all.
  std::ifstream in(std::filesystem::path(SOURCE_DIR) / "config" / "default.toml");
  std::stringstream text;
  text << in.rdbuf();
  for (const std::string& key : known_setting_keys()) {
    const std::string leaf = key.substr(key.rfind('.') + 1);
    EXPECT_NE(text.str().find("\n" + leaf + " = "), std::string::npos)
        << key << " is not in default.toml";
  }
}

TEST(Settings, CommandLineOverride) {
  Settings s;
  EXPECT_TRUE(apply_setting_override("render.shading_model=oren-nayar", s).empty());
  EXPECT_EQ(s.render.shading, ShadingModel::OrenNayar);
  EXPECT_TRUE(apply_setting_override("render.effects.fog=false", s).empty());
  EXPECT_EQ(s.render.disabled_stages, FR_FEATURE_FOG);
  EXPECT_TRUE(apply_setting_override("render.samples=4", s).empty());
  EXPECT_EQ(s.render.samples, 4);
  const auto bad = apply_setting_override("render.samples=many", s);
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_EQ(bad[0].to_string(),
            "--set render.samples=many: key 'render.samples': expected an integer in [1, 4096]");
}

}  // namespace
}  // namespace fr

namespace fr {
namespace {

// What the explorer writes back reads back to the same settings.
TEST(Settings, WrittenSettingsReadBack) {
  Settings s;
  s.plugin_folders = {"/opt/scenes", "/tmp/with \"quote\""};
  s.device = "cpu";
  s.render.shading = ShadingModel::OrenNayar;
  s.render.samples = 6;
  s.render.disabled_stages = FR_FEATURE_FOG | FR_FEATURE_GLOW;
  s.render.exposure = 1.5f;
  s.render.precision = Precision::Double;
  s.render.relaxation = 1.6f;  // the overlay's "Save settings" used to drop it
  s.render.fast_math = true;
  s.render.refine_steps = 2;
  s.render.shadow_max_steps = 48;
  s.render.ao_reference_steps = 200;
  s.render.normals = NormalMethod::Tetrahedron;
  s.explorer.window_width_px = 1920;
  s.explorer.fullscreen = true;
  s.explorer.full_quality_samples = 32;
  s.explorer.invert_y = true;
  s.explorer.key_bindings = {{"Up", "move_forward"}};
  const auto file = std::filesystem::path(TEST_OUTPUT_DIR) / "written.toml";
  std::ofstream(file) << format_settings_toml(s);
  Settings back;
  const auto problems = load_settings_file(file, back);
  ASSERT_TRUE(problems.empty()) << problems.front().to_string();
  EXPECT_EQ(back.plugin_folders, s.plugin_folders);
  EXPECT_EQ(back.device, "cpu");
  EXPECT_EQ(back.render.shading, ShadingModel::OrenNayar);
  EXPECT_EQ(back.render.samples, 6);
  EXPECT_EQ(back.render.disabled_stages, s.render.disabled_stages);
  EXPECT_EQ(back.render.exposure, 1.5f);
  EXPECT_EQ(back.render.precision, Precision::Double);
  EXPECT_EQ(back.render.relaxation, 1.6f);
  EXPECT_TRUE(back.render.fast_math);
  EXPECT_EQ(back.render.refine_steps, 2);
  EXPECT_EQ(back.render.shadow_max_steps, 48);
  EXPECT_EQ(back.render.ao_reference_steps, 200);
  EXPECT_EQ(back.render.normals, NormalMethod::Tetrahedron);
  EXPECT_EQ(back.explorer.window_width_px, 1920);
  EXPECT_TRUE(back.explorer.fullscreen);
  EXPECT_EQ(back.explorer.full_quality_samples, 32);
  EXPECT_TRUE(back.explorer.invert_y);
  EXPECT_EQ(back.explorer.key_bindings, s.explorer.key_bindings);
}

TEST(Settings, KeyBindingProblems) {
  Settings s;
  auto file = write_file("keys.toml",
                         "[controls.keys]\nfly_to_moon = \"M\"\nquit = 3\nmove_up = \"Page Up\"\n");
  auto problems = load_settings_file(file, s);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].key, "controls.keys.fly_to_moon");
  EXPECT_EQ(problems[0].line, 2);
  EXPECT_NE(problems[0].message.find("unknown action"), std::string::npos);
  EXPECT_EQ(problems[1].key, "controls.keys.quit");
  EXPECT_EQ(s.explorer.key_bindings.at("Page Up"), "move_up");
}

}  // namespace
}  // namespace fr
