// The Mandelbulber2 import: the .fract reader on hand-written snippets, the mapping (defaults,
// camera, hybrid rules, refusals) against Mandelbulber2 2.20's rules worked out here, and the
// mandelbulber scene's formula steps on the device (double) against the formulas written out in
// double in this file.
#include "import/mb2_import.hpp"
#include "cli_run.hpp"
#include "import/fract_file.hpp"
#include "import/fract_values.hpp"
#include "import/mb2_defaults.hpp"
#include "import/mb2_palette.hpp"
#include "mb2_scene_fixture.hpp"
#include "path/preset.hpp"
#include "plugin/scene_instance.hpp"
#include "render/de_probe.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>

namespace fr {
namespace {

const std::string kHeader =
    "# Mandelbulber settings file\n# version 2.20\n# only modified parameters\n";

FractFile parse(const std::string& body) {
  return parse_fract(kHeader + body, "test.fract");
}

std::string fract_error(const std::string& text) {
  try {
    parse_fract(text, "bad.fract");
  } catch (const FractError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(FractFile, ReadsBothDecimalSeparatorsColoursAndVectors) {
  const FractFile f = parse(
      "[main_parameters]\nDE_factor 0,25;\ndetail_level 1.5;\ncamera 1,5 -2,661 1e-3;\n"
      "glow_color_1 ff00 9700 0;\nperspective_type three_point;\n[fractal_1]\npower 8;\n"
      "[keyframes]\nframe;main_camera_x\n0;1,5\n");
  EXPECT_DOUBLE_EQ(fract_number(f, "DE_factor", f.main.at("DE_factor")), 0.25);
  EXPECT_DOUBLE_EQ(fract_number(f, "detail_level", f.main.at("detail_level")), 1.5);
  const auto cam = fract_vec3(f, "camera", f.main.at("camera"));
  EXPECT_DOUBLE_EQ(cam[0], 1.5);
  EXPECT_DOUBLE_EQ(cam[1], -2.661);
  EXPECT_DOUBLE_EQ(cam[2], 1e-3);
  const auto glow = fract_colour(f, "glow_color_1", f.main.at("glow_color_1"));
  EXPECT_DOUBLE_EQ(glow[0], 0xff00 / 65535.0);
  EXPECT_DOUBLE_EQ(glow[1], 0x9700 / 65535.0);
  EXPECT_DOUBLE_EQ(glow[2], 0.0);
  EXPECT_EQ(f.fractal[0].at("power").value, "8");
  EXPECT_EQ(f.main.at("camera").line, 7);  // after the 3 header lines and the section
  EXPECT_DOUBLE_EQ(f.version, 2.20);
  EXPECT_TRUE(f.only_modified);
}

// Every kind of bad input: a clear error naming the file, the line and the key.
TEST(FractFile, BadInputNamesFileLineAndKey) {
  EXPECT_NE(fract_error("").find("bad.fract: empty file"), std::string::npos);
  EXPECT_NE(fract_error("[main_parameters]\nN 5;\n").find("not a Mandelbulber settings file"),
            std::string::npos);
  EXPECT_NE(
      fract_error(kHeader + std::string("[main_parameters]\nN 5\0;\n", 23)).find("control byte"),
      std::string::npos);
  std::string noise = kHeader;
  for (int i = 0; i < 300; ++i) noise += static_cast<char>((i * 37) % 256);
  EXPECT_NE(fract_error(noise).find("bad.fract:"), std::string::npos);
  EXPECT_NE(fract_error(kHeader + "[main_parameters]\nN " + std::string(200000, '9') + ";\n")
                .find("bad.fract:5: a line of 200003 characters"),
            std::string::npos);
  EXPECT_NE(
      fract_error(kHeader + "[main_parameters]\nN 5;\nN 6;\n").find("bad.fract:6: N: given twice"),
      std::string::npos);
  EXPECT_NE(fract_error(kHeader + "N 5;\n").find("before the first section"), std::string::npos);
  const FractFile f = parse("[main_parameters]\nN 1e308;\ncamera nan nan nan;\nformula_1 abc;\n");
  try {
    fract_integer(f, "N", f.main.at("N"));
    ADD_FAILURE() << "N 1e308 read as an integer";
  } catch (const FractError& e) {
    EXPECT_NE(std::string(e.what()).find("test.fract:5: N: expected an integer"), std::string::npos)
        << e.what();
  }
  try {
    fract_vec3(f, "camera", f.main.at("camera"));
    ADD_FAILURE() << "camera nan read";
  } catch (const FractError& e) {
    EXPECT_NE(std::string(e.what()).find("test.fract:6: camera: expected three finite numbers"),
              std::string::npos)
        << e.what();
  }
}

// The defaults table: Mandelbulber2 2.20's values for the keys Fractalis reads, each once, each
// readable by the same readers as a file's values (checked here against the values its source
// initialises them to: power 9 and N 250, not 8 and 14).
TEST(Mb2Defaults, TableHoldsMandelbulber2Values) {
  const FractFile none = parse("[main_parameters]\n");
  std::set<std::string> keys;
  for (const Mb2Default& d : mb2_main_defaults()) EXPECT_TRUE(keys.insert(d.key).second) << d.key;
  for (const Mb2Default& d : mb2_fractal_defaults())
    EXPECT_TRUE(keys.insert(d.key).second) << d.key;
  auto main_number = [&](const char* key) {
    return fract_number(none, key, mb2_main_entry(none, key));
  };
  EXPECT_EQ(fract_integer(none, "N", mb2_main_entry(none, "N")), 250);
  EXPECT_EQ(fract_integer(none, "formula_1", mb2_main_entry(none, "formula_1")), 2);
  EXPECT_EQ(main_number("fov"), 1);
  EXPECT_EQ(main_number("bailout"), 100);
  EXPECT_EQ(main_number("detail_level"), 1);
  EXPECT_EQ(main_number("view_distance_max"), 50);
  EXPECT_TRUE(fract_bool(none, "use_default_bailout", mb2_main_entry(none, "use_default_bailout")));
  const auto camera = fract_vec3(none, "camera", mb2_main_entry(none, "camera"));
  EXPECT_EQ(camera, (std::array<double, 3>{3, -6, 2}));
  EXPECT_EQ(fract_number(none, "power", mb2_fractal_entry(none, 0, "power")), 9);
  EXPECT_EQ(fract_number(none, "mandelbox_scale", mb2_fractal_entry(none, 0, "mandelbox_scale")),
            2);
  EXPECT_EQ(fract_vec3(none, "IFS_offset", mb2_fractal_entry(none, 0, "IFS_offset")),
            (std::array<double, 3>{1, 0, 0}));
  // A file's own value wins over the default.
  const FractFile given = parse("[main_parameters]\nN 12;\n[fractal_2]\npower 3;\n");
  EXPECT_EQ(fract_integer(given, "N", mb2_main_entry(given, "N")), 12);
  EXPECT_EQ(fract_number(given, "power", mb2_fractal_entry(given, 1, "power")), 3);
  EXPECT_EQ(fract_number(given, "power", mb2_fractal_entry(given, 0, "power")), 9);
}

toml::table preset_of(const Mb2Import& imported) {
  EXPECT_TRUE(imported.faithful()) << (imported.refusals().empty() ? "" : imported.refusals()[0]);
  return toml::parse(imported.preset_toml);
}

double num(const toml::table& t, const char* table, const char* key) {
  return t[table][key].value<double>().value_or(NAN);
}

// An absent key takes Mandelbulber2 2.20's default: the power-9 bulb, N 250, bailout 10, the
// camera at (3, -6, 2).
TEST(Mb2Import, AbsentKeysTakeMandelbulber2Defaults) {
  const toml::table t = preset_of(import_fract(parse("[main_parameters]\n"), "x"));
  EXPECT_EQ(t["scene"].value<std::string>(), "mandelbulber");
  EXPECT_EQ(t["params"]["f1"].value<std::string>(), "mandelbulb");
  EXPECT_EQ(t["params"]["f2"].value<std::string>(), "none");
  EXPECT_DOUBLE_EQ(num(t, "params", "bulb_power"), 9);
  EXPECT_EQ(t["params"]["iterations"].value<int64_t>(), 250);
  EXPECT_DOUBLE_EQ(num(t, "params", "bailout"), 10);
  EXPECT_EQ(t["params"]["estimate"].value<std::string>(), "logarithmic");
  EXPECT_DOUBLE_EQ(t["camera"]["eye"][1].value<double>().value_or(0), -6);
  EXPECT_DOUBLE_EQ(num(t, "settings", "render.hit_threshold_k"), 1);
}

// Mandelbulber2's fov is the image plane's height at unit distance; the preset's fov_deg is the
// horizontal angle at the file's aspect: 2 atan(fov * w / h / 2).
TEST(Mb2Import, FieldOfViewFromTheImagePlane) {
  const toml::table t = preset_of(import_fract(
      parse("[main_parameters]\nfov 0,6;\nimage_width 1600;\nimage_height 900;\n"), "x"));
  EXPECT_NEAR(num(t, "camera", "fov_deg"),
              2 * std::atan(0.6 * 16.0 / 9.0 / 2) * 180 / std::numbers::pi, 1e-9);
  // Mandelbulber2's pixel grid (camera_test.cpp checks the rays), the picture not mirrored.
  EXPECT_EQ(t["settings"]["render.pixel_corners"].value<bool>(), true);
  EXPECT_EQ(t["settings"]["render.mirror_vertical"].value<bool>(), false);
}

// A hybrid: the estimate family with the most iterations (linear on a tie), the largest default
// bailout, c added as each formula's rule says (the Menger sponge's inverted).
TEST(Mb2Import, HybridRules) {
  const toml::table t = preset_of(import_fract(
      parse("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 2;\nformula_2 8;\n"
            "formula_3 7;\nformula_iterations_1 3;\ndont_add_c_constant_3 true;\n"),
      "x"));
  EXPECT_EQ(t["params"]["f2"].value<std::string>(), "mandelbox");
  EXPECT_EQ(t["params"]["f3"].value<std::string>(), "menger");
  // logarithmic 3 iterations (bulb) against linear 2 (box and sponge): logarithmic.
  EXPECT_EQ(t["params"]["estimate"].value<std::string>(), "logarithmic");
  EXPECT_DOUBLE_EQ(num(t, "params", "bailout"), 100);
  EXPECT_EQ(t["params"]["f2_add_c"].value<bool>(), true);
  EXPECT_EQ(t["params"]["f3_add_c"].value<bool>(), true);  // dont_add_c on the sponge adds it
  const toml::table tie = preset_of(import_fract(
      parse("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 2;\nformula_2 8;\n"), "x"));
  EXPECT_EQ(tie["params"]["estimate"].value<std::string>(), "linear");
  const toml::table single =
      preset_of(import_fract(parse("[main_parameters]\nformula_1 7;\n"), "x"));
  EXPECT_EQ(single["params"]["estimate"].value<std::string>(), "ifs");
  EXPECT_EQ(single["params"]["f1_add_c"].value<bool>(), false);
}

// The main light: (sin a cos b, -cos a cos b, sin b) towards the light in the camera's frame
// (x right, y forward, z up). Looking along +y with z up, the default a = -45, b = 45 degrees is
// towards (-0.5, -0.5, 0.7071): the key light travels the opposite way.
TEST(Mb2Import, MainLightRelativeToTheCamera) {
  const toml::table t = preset_of(
      import_fract(parse("[main_parameters]\ncamera 0 -6 0;\ntarget 0 0 0;\ncamera_top 0 0 1;\n"
                         "main_light_colour ffff 8000 0;\nmain_light_intensity 2;\n"),
                   "x"));
  const toml::array* lights = t["lights"].as_array();
  ASSERT_TRUE(lights && lights->size() == 2) << "the key light, and the fill light off";
  const toml::table& key = *lights->get(0)->as_table();
  const double expected[3] = {0.5, 0.5, -std::sqrt(0.5)};
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(key["direction"][i].value<double>().value_or(NAN), expected[i], 1e-12) << i;
  EXPECT_NEAR(key["color"][1].value<double>().value_or(NAN), srgb_to_linear(0x8000 / 65535.0),
              1e-12);
  EXPECT_NEAR(key["intensity"].value<double>().value_or(NAN), 2.6, 1e-12);
}

// The auxiliary lights: point lights 3 to 6 of the mandelbulber scene (an empty entry keeps its
// fill light and the lights not enabled), at Mandelbulber2's position and colour, intensity
// 1.3 * 100 / 24 of its own (its 100 I / (d^2 4 6), the key light's 1.3 for its 1), falling
// off as 1 / (1 + d^2).
TEST(Mb2Import, AuxiliaryLightsArePointLights) {
  // The view 5 long: d0 = 0.05, a = 400.
  const toml::table t = preset_of(import_fract(
      parse("[main_parameters]\ncamera 0 -5 0;\ntarget 0 0 0;\naux_light_enabled_2 true;\n"
            "aux_light_position_2 1 2 -3;\naux_light_intensity_2 2;\n"
            "aux_light_colour_2 ffff 0 8000;\n"),
      "x"));
  const toml::array* lights = t["lights"].as_array();
  ASSERT_TRUE(lights && lights->size() == 4) << "main, fill, aux 1 (off), aux 2";
  EXPECT_EQ((*lights->get(1)->as_table())["intensity"].value<double>(), 0.0)
      << "the fill light off: Mandelbulber2 has none";
  EXPECT_TRUE(lights->get(2)->as_table()->empty());
  const toml::table& aux = *lights->get(3)->as_table();
  const double position[3] = {1, 2, -3};
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(aux["position"][i].value<double>().value_or(NAN), position[i]) << i;
  const double a = 1 / (0.05 * 0.05);
  EXPECT_NEAR(aux["attenuation"].value<double>().value_or(NAN), a, 1e-9);
  EXPECT_NEAR(aux["intensity"].value<double>().value_or(NAN), 1.3 * 100 / 24 * 2 * a, 1e-9);
  EXPECT_NEAR(aux["color"][2].value<double>().value_or(NAN), srgb_to_linear(0x8000 / 65535.0),
              1e-12);
  EXPECT_EQ(aux["falloff"].value<double>(), 2.0);
  // Beyond d0 the light falls off as Mandelbulber2's 100 I / (24 d^2), times the key light's 1.3.
  for (double d : {0.5, 2.0, 7.0})
    EXPECT_NEAR(1.3 * 100 / 24 * 2 * a / (1 + a * d * d), 1.3 * 100 * 2 / (24 * d * d),
                0.01 * 1.3 * 100 * 2 / (24 * d * d))
        << d;
  // None enabled: the main light, and the fill light off.
  const toml::table none = preset_of(import_fract(parse("[main_parameters]\n"), "x"));
  EXPECT_EQ(none["lights"].as_array()->size(), 2u);
}

// The background as the sky's gradient (zenith background_color_1, horizon background_color_2,
// times background_brightness), or background_color_1 alone; depth of field as a thin lens of
// radius focus fov DOF_radius (1 + aspect) / 2000, the blur Mandelbulber2's post-process gives.
TEST(Mb2Import, BackgroundAndDepthOfField) {
  const toml::table t = preset_of(import_fract(
      parse("[main_parameters]\nbackground_color_1 ffff 0 0;\nbackground_color_2 0 ffff 0;\n"
            "background_brightness 2;\nDOF_enabled true;\nDOF_focus 4;\nDOF_radius 10;\n"
            "fov 1;\nimage_width 800;\nimage_height 600;\n"),
      "x"));
  const toml::table& settings = *t["settings"].as_table();
  EXPECT_EQ(settings["render.sky_zenith"][0].value<double>(), 2.0);
  EXPECT_EQ(settings["render.sky_zenith"][1].value<double>(), 0.0);
  EXPECT_EQ(settings["render.sky_horizon"][1].value<double>(), 2.0);
  EXPECT_EQ(settings["render.effects.dof"].value<bool>(), true);
  EXPECT_EQ(settings["render.focus_distance"].value<double>(), 4.0);
  EXPECT_NEAR(settings["render.aperture"].value<double>().value_or(NAN),
              4.0 * 1.0 * 10 * (1 + 800.0 / 600) / 2000, 1e-12);
  const toml::table one = preset_of(import_fract(
      parse("[main_parameters]\nbackground_3_colors_enable false;\nbackground_color_1 0 0 ffff;\n"),
      "x"));
  EXPECT_EQ(one["settings"]["render.sky_horizon"][2].value<double>(), 1.0);
  EXPECT_EQ(one["settings"]["render.sky_zenith"][2].value<double>(), 1.0);
  EXPECT_EQ(one["settings"]["render.effects.dof"].value<bool>(), false);
}

std::vector<std::string> refusals(const std::string& body) {
  return import_fract(parse(body), "x").refusals();
}

TEST(Mb2Import, RefusesWhatWouldChangeTheShape) {
  auto has = [](const std::vector<std::string>& r, const std::string& text) {
    for (const auto& s : r)
      if (s == text) return true;
    ADD_FAILURE() << "no refusal '" << text << "' in " << r.size() << " refusals"
                  << (r.empty() ? "" : ": " + r[0]);
    return false;
  };
  has(refusals("[main_parameters]\nformula_1 16;\n"),
      "slot 1: formula 16 (box_fold_bulb_pow2) is not supported");
  has(refusals("[main_parameters]\nhybrid_fractal_enable true;\nformula_2 16;\n"),
      "slot 2: formula 16 (box_fold_bulb_pow2) is not supported");
  has(refusals("[main_parameters]\nprimitive_water_1_enabled true;\n"),
      "primitive_water_1: primitives are not supported");
  has(refusals("[main_parameters]\nboolean_operators true;\n"), "boolean_operators: not supported");
  has(refusals("[main_parameters]\nperspective_type equirectangular;\n"),
      "perspective_type equirectangular: not supported");
  EXPECT_EQ(refusals("[main_parameters]\nperspective_type 0;\n").size(), 0u);
  EXPECT_EQ(refusals("[main_parameters]\nprimitive_water_1_enabled false;\n").size(), 0u);
  EXPECT_EQ(
      parse_fract("# Mandelbulber settings file\n# version 2.25\n[main_parameters]\n", "n.fract")
          .version,
      2.25);
  EXPECT_EQ(
      import_fract(parse_fract("# Mandelbulber settings file\n# version 2.25\n[main_parameters]\n",
                               "n.fract"),
                   "x")
          .faithful(),
      false);
  has(refusals("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 8;\n"
               "[fractal_2]\nmandelbox_scale -1,5;\n"),
      "slot 2: formula 8 (mandelbox) in slot 1 too, with another mandelbox_scale: two different "
      "sets are not supported");
  EXPECT_EQ(refusals("[main_parameters]\nhybrid_fractal_enable true;\nformula_1 8;\nformula_2 8;\n")
                .size(),
            0u);
}

// A preset's [[lights]] replace the scene's first lights (directional, or point lights with a
// position), and anything wrong in them is reported with its line, leaving the state as it was.
TEST(PresetLights, ReplaceTheFirstLightsOrAreReported) {
  const auto scene =
      test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulber" PLUGIN_SUFFIX);
  ASSERT_TRUE(scene);
  auto preset = [](const std::string& lights) {
    std::vector<std::string> problems;
    auto p = preset_from_text("scene = \"mandelbulber\"\nname = \"x\"\n" + lights, "p.toml", "p",
                              &problems);
    EXPECT_TRUE(p) << (problems.empty() ? "" : problems[0]);
    return *p;
  };
  SceneState state = make_default_state(scene->info);
  const fr_light fill = state.lights.at(1);
  EXPECT_TRUE(apply_preset(preset("[[lights]]\ndirection = [0, 0, -1]\ncolor = [1, 0.5, 0]\n"
                                  "intensity = 2.5\n"),
                           scene->info, state)
                  .empty());
  EXPECT_EQ(state.lights[0].kind, FR_LIGHT_DIRECTIONAL);
  EXPECT_EQ(state.lights[0].vector[2], -1);
  EXPECT_EQ(state.lights[0].color[1], 0.5);
  EXPECT_EQ(state.lights[0].intensity, 2.5);
  EXPECT_EQ(state.lights[1].vector[0], fill.vector[0]) << "the second light is the scene's";
  const SceneState before = state;
  auto first = [&](const std::string& lights) {
    const auto problems = apply_preset(preset(lights), scene->info, state);
    EXPECT_EQ(state.lights[0].intensity, before.lights[0].intensity) << "state left as it was";
    return problems.empty() ? std::string("(none)") : problems[0];
  };
  EXPECT_NE(first("[[lights]]\ndirection = [0, 0, 0]\n").find("p.toml:4: direction"),
            std::string::npos);
  EXPECT_NE(first("[[lights]]\ncolour = [1, 1, 1]\n").find("unknown light key 'colour'"),
            std::string::npos);
  std::string seven;
  for (int i = 0; i < 7; ++i) seven += "[[lights]]\n";
  EXPECT_NE(first(seven).find("7 lights, and scene 'mandelbulber' has 6"), std::string::npos);
  EXPECT_NE(first("[[lights]]\nintensity = -1\n").find("intensity: expected"), std::string::npos);
  EXPECT_NE(first("[[lights]]\ndirection = [0, 0, -1]\nposition = [1, 1, 1]\n")
                .find("a direction or a position, not both"),
            std::string::npos);
  EXPECT_NE(first("[[lights]]\nposition = [1, 1, 1]\nfalloff = 0\n").find("falloff: expected"),
            std::string::npos);
  // With a position, a point light: its attenuation and falloff as given; an empty entry keeps
  // the scene's light.
  SceneState lit = make_default_state(scene->info);
  EXPECT_TRUE(apply_preset(preset("[[lights]]\n[[lights]]\nposition = [1, -2, 3]\n"
                                  "intensity = 4\nattenuation = 0.5\nfalloff = 1\n"),
                           scene->info, lit)
                  .empty());
  EXPECT_EQ(lit.lights[0].vector[0], make_default_state(scene->info).lights[0].vector[0]) << "kept";
  EXPECT_EQ(lit.lights[1].kind, FR_LIGHT_POINT);
  EXPECT_EQ(lit.lights[1].vector[1], -2);
  EXPECT_EQ(lit.lights[1].intensity, 4);
  EXPECT_EQ(lit.lights[1].attenuation, 0.5);
  EXPECT_EQ(lit.lights[1].falloff, 1);
}

// A preset's [settings] are render settings only: one from elsewhere that would turn plugin
// isolation off is refused by line, and the settings stay as they were.
TEST(PresetSettings, OnlyRenderSettings) {
  std::vector<std::string> problems;
  const auto p = preset_from_text(
      "scene = \"mandelbulber\"\nname = \"x\"\n[settings]\n\"render.hit_threshold_k\" = 2.0\n"
      "\"plugins.isolation\" = \"none\"\n",
      "p.toml", "p", &problems);
  ASSERT_TRUE(p) << (problems.empty() ? "" : problems[0]);
  Settings settings;
  const PluginIsolation isolation = settings.plugins.isolation;
  const auto wrong = apply_preset_settings(*p, settings);
  ASSERT_EQ(wrong.size(), 1u);
  EXPECT_NE(wrong[0].find("p.toml:5: [settings] plugins.isolation: a preset sets render.* "
                          "settings only"),
            std::string::npos)
      << wrong[0];
  EXPECT_EQ(settings.plugins.isolation, isolation);
  EXPECT_EQ(settings.render.hit_threshold_k, 2.0f);
}

// The scene's DE on the device, in double, against the formulas written out here.
class Mb2De : public test::Mb2SceneTest {
 protected:
  float de(std::array<float, 3> p) {
    return probe_de(test::runtime(), scene->info, values, {p}, 16, Precision::Double)[0];
  }
};

struct V4 {
  double x, y, z, w;
  double length() const { return std::sqrt(x * x + y * y + z * z + w * w); }
};

double log_estimate(double r, double dr) {
  return std::clamp(0.5 * r * std::log(r) / dr, 0.0, 10.0);
}

// The power-2 bulb's map at a point, one iteration, c = p.
TEST_F(Mb2De, Power2MapAtAPoint) {
  choose("f1", "power2");
  set("iterations", 1);
  const double x = 0.5, y = 0.3, z = 0.2;
  const double s = x * x + y * y, t = 1 - z * z / s;
  V4 q{(x * x - y * y) * t + x, 2 * x * y * t + y, -2 * z * std::sqrt(s) + z, 0};
  const double dr = 2 * std::sqrt(x * x + y * y + z * z);
  EXPECT_NEAR(de({0.5f, 0.3f, 0.2f}), log_estimate(q.length(), dr), 1e-6);
}

// The hypercomplex square at a point, one iteration: w becomes -2 y z and counts in r.
TEST_F(Mb2De, HypercomplexMapAtAPoint) {
  choose("f1", "hypercomplex");
  set("iterations", 1);
  const double x = 0.6, y = -0.4, z = 0.7;
  V4 q{x * x - y * y - z * z + x, 2 * x * y + y, 2 * x * z + z, -2 * y * z};
  const double dr = 2 * std::sqrt(x * x + y * y + z * z);
  EXPECT_NEAR(de({0.6f, -0.4f, 0.7f}), log_estimate(q.length(), dr), 1e-6);
}

// A kaleidoscopic IFS plane's reflection: normal (0, 0, 1) at distance 0.1 reflects z = -0.5 to
// 0.7; then scale 2 about the offset (1, 0, 0): (-0.4, 0.4, 1.4), linear estimate r / 2.
TEST_F(Mb2De, KifsPlaneReflection) {
  choose("f1", "kifs");
  choose("estimate", "linear");
  set("iterations", 1);
  set("bailout", 100);
  set("f1_add_c", 0);
  set("kifs_plane0", 1);
  set3("kifs_plane0_direction", 0, 0, 1);
  set("kifs_plane0_distance", 0.1);
  EXPECT_NEAR(de({0.3f, 0.2f, -0.5f}), std::sqrt(0.16 + 0.16 + 1.96) / 2, 1e-6);
  // Above the plane nothing is reflected: (0.6, 0.4, 0.4) - (1, 0, 0).
  EXPECT_NEAR(de({0.3f, 0.2f, 0.2f}), std::sqrt(0.16 + 0.16 + 0.16) / 2, 1e-6);
}

// Mandelbulber2's bulb (latitude by asin) with beta = 90/p - 90 degrees is the classic (acos)
// bulb: the same DE as the mandelbulb scene's at random points, power 8, the same bailout.
TEST_F(Mb2De, AsinBulbWithBetaOffsetIsTheAcosBulb) {
  const double power = 8;
  set("bulb_power", power);
  set("bulb_beta", 90 / power - 90);
  set("iterations", 12);
  set("bailout", 2);
  auto classic = test::mandelbulb();
  ASSERT_TRUE(classic);
  auto classic_values = make_default_state(classic->info).params;
  auto put = [&](const char* key, double v) {
    const int i = classic->info.find_param(key);
    ASSERT_GE(i, 0) << key;
    classic_values[i].v[0] = v;
  };
  put("power", power);
  put("iterations", 12);
  put("bailout", 2);
  std::vector<std::array<float, 3>> points;
  for (int i = 0; i < 64; ++i)
    points.push_back({static_cast<float>(std::sin(i * 1.7) * 1.1),
                      static_cast<float>(std::cos(i * 2.3) * 1.1),
                      static_cast<float>(std::sin(i * 0.9 + 1) * 1.1)});
  const auto ours = probe_de(test::runtime(), scene->info, values, points, 16, Precision::Double);
  const auto theirs =
      probe_de(test::runtime(), classic->info, classic_values, points, 16, Precision::Double);
  int compared = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!(theirs[i] > 1e-4f && theirs[i] < 10)) continue;  // Mandelbulber2 keeps [0, 10]
    EXPECT_NEAR(ours[i], theirs[i], 1e-4 * theirs[i]) << "point " << i;
    ++compared;
  }
  EXPECT_GT(compared, 20);
}

// Mandelbulber2's bulb step (id 2) written out with its trigonometry: theta = asin(z/r) + beta,
// phi = atan2(y, x) + alpha, both times the power, r the 4D length, w untouched.
void mb2_bulb_reference(V4& z, double& dr, double power, double alpha_deg, double beta_deg) {
  const double r = z.length(), k = M_PI / 180;
  const double th = (std::asin(z.z / r) + beta_deg * k) * power;
  const double ph = (std::atan2(z.y, z.x) + alpha_deg * k) * power;
  const double rp1 = std::pow(r, power - 1);
  dr = rp1 * power * dr + 1;
  const double rp = rp1 * r;
  z = V4{rp * std::cos(th) * std::cos(ph), rp * std::cos(th) * std::sin(ph), rp * std::sin(th),
         z.w};
}

// The bulb with both angle offsets, at a whole power (the kernel's path without trigonometry) and
// a fractional one (its trigonometric path), against the step written out above: five iterations
// of z <- bulb(z) + p from points in and around the set.
TEST_F(Mb2De, BulbWithAngleOffsetsAtWholeAndFractionalPowers) {
  for (const double power : {9.0, 3.0, 8.5}) {
    set("bulb_power", power);
    set("bulb_alpha", 17);
    set("bulb_beta", -23);
    set("iterations", 5);
    set("bailout", 4);
    std::vector<std::array<float, 3>> points;
    for (int i = 0; i < 48; ++i)
      points.push_back({static_cast<float>(std::sin(i * 1.3) * 1.2),
                        static_cast<float>(std::cos(i * 2.9) * 1.2),
                        static_cast<float>(std::sin(i * 0.7 + 2) * 1.2)});
    points.push_back({0, 0, 0.7f});  // on the z axis: phi is alpha there
    const auto ours = probe_de(test::runtime(), scene->info, values, points, 16, Precision::Double);
    int compared = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const V4 p{points[i][0], points[i][1], points[i][2], 0};
      V4 z = p;
      double dr = 1;
      for (int n = 0; n < 5; ++n) {
        mb2_bulb_reference(z, dr, power, 17, -23);
        z = V4{z.x + p.x, z.y + p.y, z.z + p.z, 0};
        if (z.length() > 4) break;
      }
      const double expected = log_estimate(z.length(), dr);
      if (!(expected > 1e-3 && expected < 10)) continue;
      EXPECT_NEAR(ours[i], expected, 1e-5 * expected) << "power " << power << ", point " << i;
      ++compared;
    }
    EXPECT_GT(compared, 20) << "power " << power;
  }
}

// A bulb after a hypercomplex step sees w: r is 4D, and so is the latitude's cosine
// (|(x, y, w)| / r). Slot 1 hypercomplex (w <- 2 x w - 2 y z), slot 2 bulb power 4, one each.
TEST_F(Mb2De, BulbAfterHypercomplexCountsW) {
  set("hybrid", 1);
  set("iterations", 2);
  choose("f1", "hypercomplex");
  choose("f2", "mandelbulb");
  set("bulb_power", 4);
  set("bulb_beta", 10);
  set("bailout", 1e6);
  const V4 p{0.75, -0.625, 0.5, 0};  // exact in float
  V4 z{p.x * p.x - p.y * p.y - p.z * p.z + p.x, 2 * p.x * p.y + p.y, 2 * p.x * p.z + p.z,
       -2 * p.y * p.z};
  double dr = 2 * p.length();
  mb2_bulb_reference(z, dr, 4, 0, 10);
  z = V4{z.x + p.x, z.y + p.y, z.z + p.z, z.w};
  const double expected = log_estimate(z.length(), dr);
  ASSERT_GT(expected, 1e-3);
  EXPECT_NEAR(de({0.75f, -0.625f, 0.5f}), expected, 1e-5 * expected);
}

// The hybrid sequence by hand: slot 1 (bulb, power 2, two in a row), slot 2 (power-2 bulb), N = 3:
// bulb, bulb, power2, each followed by + c.
TEST_F(Mb2De, HybridSequenceByHand) {
  set("hybrid", 1);
  set("iterations", 3);
  set("bulb_power", 2);
  set("f1_iterations", 2);
  choose("f2", "power2");
  set("bailout", 1e6);
  const V4 p{0.3, -0.2, 0.25, 0};
  V4 z = p;
  double dr = 1;
  auto bulb = [&] {
    const double r = z.length();
    const double th = std::asin(z.z / r) * 2, ph = std::atan2(z.y, z.x) * 2;
    dr = 2 * r * dr + 1;
    z = V4{r * r * std::cos(th) * std::cos(ph) + p.x, r * r * std::cos(th) * std::sin(ph) + p.y,
           r * r * std::sin(th) + p.z, 0};
  };
  auto pow2 = [&] {
    const double r = z.length();
    const double s = z.x * z.x + z.y * z.y, t = 1 - z.z * z.z / s;
    dr = 2 * r * dr;
    z = V4{(z.x * z.x - z.y * z.y) * t + p.x, 2 * z.x * z.y * t + p.y,
           -2 * z.z * std::sqrt(s) + p.z, 0};
  };
  bulb();
  bulb();
  pow2();
  EXPECT_NEAR(de({0.3f, -0.2f, 0.25f}), log_estimate(z.length(), dr),
              1e-6 * std::max(1.0, log_estimate(z.length(), dr)));
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// `fractalis import`: 0 and a preset that `render --preset` takes for a faithful import; 1 with
// one line per reason and nothing written for a refused one; 2 for a file that is not one.
TEST(Mb2ImportCli, ExitCodesAndWhatIsWritten) {
  const auto dir = test::fresh_dir("mb2_import_cli");
  const auto good = dir / "My Sponge 1.fract";
  write_text(good, kHeader + "[main_parameters]\nformula_1 7;\ncamera 3 -2 1,5;\nN 12;\n");
  test::CliRun r = test::run({"import", good.string(), "--out", dir.string()});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("mapped: slot 1: formula 7 -> f1 = menger"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "my_sponge_1.toml")) << r.out;

  const auto refused = dir / "refused.fract";
  write_text(refused,
             kHeader + "[main_parameters]\nformula_1 16;\nprimitive_water_1_enabled true;\n");
  r = test::run({"import", refused.string(), "--out", dir.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("refused: slot 1: formula 16 (box_fold_bulb_pow2) is not supported\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("refused: primitive_water_1: primitives are not supported\n"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "refused.toml"));

  const auto noise = dir / "noise.fract";
  write_text(noise, std::string("\x7f"
                                "ELF\x02\x01\x01\0\0\0",
                                10));
  test::expect_usage_error({"import", noise.string(), "--out", dir.string()}, "noise.fract:1:");
  EXPECT_FALSE(std::filesystem::exists(dir / "noise.toml"));
  test::expect_usage_error(
      {"render", "--preset", refused.string(), "--out", (dir / "x.png").string()},
      "slot 1: formula 16 (box_fold_bulb_pow2) is not supported");
  test::expect_usage_error({"import", (dir / "missing.fract").string()}, "cannot be opened");
}

// The .fract file itself as --preset: the imported view and settings render (the sponge from
// outside: the middle pixel hits it).
TEST(Mb2ImportCli, RenderTakesTheFractFile) {
  const auto dir = test::fresh_dir("mb2_render_preset");
  const auto file = dir / "sponge.fract";
  write_text(file, kHeader +
                       "[main_parameters]\nformula_1 7;\ncamera 3 -2 1,5;\nN 8;\n"
                       "legacy_coordinate_system true;\nimage_width 64;\nimage_height 48;\n");
  const auto out = dir / "sponge.exr";
  const test::CliRun r =
      test::run({"render", "--preset", file.string(), "--size", "64x48", "--out", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
}

// Every example Debian's mandelbulber2-data installs (scripts/common.sh installs it) is read and
// imported or refused, none unreadable, and at least 119 import.
TEST(Mb2ImportExamples, EveryExampleImportsOrIsRefused) {
  const std::filesystem::path dir = "/usr/share/mandelbulber2/examples";
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "mandelbulber2-data is not installed";
  size_t files = 0, imported = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".fract") continue;
    ++files;
    try {
      const Mb2Import result = import_fract(load_fract(entry.path()), "x");
      if (result.faithful()) {
        ++imported;
        EXPECT_FALSE(result.preset_toml.empty());
      } else {
        EXPECT_FALSE(result.refusals().empty());
      }
    } catch (const FractError& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_EQ(files, 422u);
  EXPECT_GE(imported, 119u);
}

}  // namespace
}  // namespace fr
