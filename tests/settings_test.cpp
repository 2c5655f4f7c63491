// The settings loader's errors: file, line, key and what was expected; unknown keys named with
// the nearest known key; good values still apply when another is wrong.
#include "settings/settings.hpp"
#include "settings/settings_table.hpp"
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

// config/default.toml is what the settings table writes for the built-in defaults, and it loads
// back to them. On a mismatch the table's text is left in the build folder to copy over.
TEST(Settings, DefaultFileIsTheTablesOutput) {
  const auto file = std::filesystem::path(SOURCE_DIR) / "config" / "default.toml";
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string expected = default_settings_toml();
  if (text.str() != expected) {
    const auto fresh = std::filesystem::path(TEST_OUTPUT_DIR) / "default.toml";
    std::ofstream(fresh) << expected;
    ADD_FAILURE() << "config/default.toml is not what host/settings/settings_table.cpp writes; "
                     "if the table is right: cp "
                  << fresh << " " << file;
  }
  Settings from_file;
  const auto problems = load_settings_file(file, from_file);
  EXPECT_TRUE(problems.empty()) << problems.front().to_string();
  const Settings builtin;
  for (const SettingSpec& spec : settings_table())
    EXPECT_EQ(spec.get(from_file), spec.get(builtin)) << spec.key;
}

// A value other than the default for every key, from the key's own range or choices.
// A Radiance panorama (16 x 8 pixels of 1.0, flat RGBE) under a name with a quote and a
// backslash (on Linux; Windows allows neither in a name), for a setting that must name a
// readable file (render.environment).
std::string panorama_file() {
  const bool windows = std::filesystem::path::preferred_separator == '\\';
  const auto file = std::filesystem::path(TEST_OUTPUT_DIR) /
                    (windows ? "sky 'quoted' back.hdr" : "sky \"quoted\" \\ back.hdr");
  std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n";
  for (int i = 0; i < 16 * 8; ++i) bytes += "\x80\x80\x80\x81";
  std::ofstream(file, std::ios::binary) << bytes;
  return file.string();
}

SettingValue other_value(const SettingSpec& spec, const SettingValue& now) {
  switch (spec.kind) {
    case SettingKind::Bool:
      return !std::get<bool>(now);
    case SettingKind::Int:
      if (!spec.only_ints.empty())
        return spec.only_ints.back() == std::get<long long>(now) ? spec.only_ints.front()
                                                                 : spec.only_ints.back();
      return std::get<long long>(now) == static_cast<long long>(spec.max)
                 ? static_cast<long long>(spec.min)
                 : static_cast<long long>(spec.max);
    case SettingKind::Number: {
      // A value with many digits, to catch a writer that rounds: 1/3 of the way up the range.
      const double v = spec.min + (spec.max - spec.min) / 3.0;
      return v == std::get<double>(now) ? spec.max : v;
    }
    case SettingKind::Choice:
      for (const SettingChoice& c : spec.choices)
        if (c.name != std::get<std::string>(now)) return std::string(c.name);
      return now;
    case SettingKind::Text:
      if (spec.check) return panorama_file();
      return std::string("gpu \"quoted\" \\ back");
    case SettingKind::TextList:
      return std::vector<std::string>{"/opt/scenes", "/tmp/with \"quote\""};
    case SettingKind::Color:
      // Digits a float keeps only in part, to catch a writer that rounds further.
      return SettingColor{0.1, 1.0 / 3.0, spec.max / 7.0};
  }
  return now;
}

// Every key, set to a value other than its default, is written and read back unchanged: what
// the overlay's "Save settings" writes loses nothing (it used to drop render.relaxation).
TEST(Settings, EveryKeyRoundTripsThroughSaveAndLoad) {
  Settings s;
  for (const SettingSpec& spec : settings_table()) {
    const SettingValue v = other_value(spec, spec.get(s));
    ASSERT_NE(v, spec.get(s)) << spec.key << " has no second value to test with";
    ASSERT_EQ(check_setting(spec, v), "") << spec.key;
    spec.set(s, v);
  }
  s.explorer.key_bindings = {{"Up", "move_forward"}, {"Page Down", "move_down"}};
  const auto file = std::filesystem::path(TEST_OUTPUT_DIR) / "every_key.toml";
  std::ofstream(file) << format_settings_toml(s, "every key");
  Settings back;
  const auto problems = load_settings_file(file, back);
  ASSERT_TRUE(problems.empty()) << problems.front().to_string();
  for (const SettingSpec& spec : settings_table()) {
    EXPECT_EQ(spec.get(back), spec.get(s)) << spec.key;
    EXPECT_NE(spec.get(back), spec.get(Settings{})) << spec.key << " came back as the default";
  }
  EXPECT_EQ(back.explorer.key_bindings, s.explorer.key_bindings);
}

// Each enum's names come from its table, and the kernel's switch macros are numbered by table
// row: the defines for the chosen model name that model, whatever the enum's order.
// A value no table lists is a bug in fractalis: FR_CHECK stops with the place, instead of the
// first row's name standing in for it.
TEST(Settings, AnEnumValueWithoutANameIsAnInternalError) {
  EXPECT_DEATH(enum_name(static_cast<ShadingModel>(99)),
               "internal error at .*enum_names.hpp:.*: an enum value has no row");
}

TEST(Settings, EnumNamesComeFromTheirTables) {
  EXPECT_STREQ(enum_name(ShadingModel::OrenNayar), "oren-nayar");
  EXPECT_EQ(enum_from_name<FogMethod>("power"), FogMethod::PowerLaw);
  EXPECT_FALSE(enum_from_name<FogMethod>("Power").has_value());
  EXPECT_EQ(enum_name_list<Precision>(), "auto, float, double or dd");
  const SettingSpec* shading = find_setting("render.shading_model");
  ASSERT_NE(shading, nullptr);
  ASSERT_EQ(shading->choices.size(), std::size(kShadingModelNames));
  EXPECT_STREQ(shading->choices[2].name, "oren-nayar");
}

TEST(Settings, CommandLineOverride) {
  Settings s;
  EXPECT_TRUE(apply_setting_override("render.shading_model=oren-nayar", s).empty());
  EXPECT_EQ(s.render.shading, ShadingModel::OrenNayar);
  EXPECT_TRUE(apply_setting_override("render.effects.fog=false", s).empty());
  EXPECT_EQ(s.render.disabled_stages, FR_FEATURE_FOG);
  EXPECT_TRUE(apply_setting_override("render.samples=4", s).empty());
  // An integer where a number goes is that number.
  EXPECT_TRUE(apply_setting_override("render.watchdog_s=2", s).empty());
  EXPECT_EQ(s.render.watchdog_s, 2.0);
  EXPECT_TRUE(apply_setting_override("render.exposure=3", s).empty());
  EXPECT_EQ(s.render.exposure, 3.0f);
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
  std::ofstream(file) << format_settings_toml(s, "test");
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
