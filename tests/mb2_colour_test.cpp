// Mandelbulber2's palette colouring: the gradient reader (mb2_palette) on hand-written gradients
// and palettes, the importer's colour keys, and the mandelbulber scene's colouring pass on the
// device (double) against Mandelbulber2 2.20's rules written out here: its colouring pass over
// the orbit, its colour index per formula, its palette position.
#include "import/fract_file.hpp"
#include "import/mb2_import.hpp"
#include "import/mb2_palette.hpp"
#include "mb2_scene_fixture.hpp"
#include "render/de_probe.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace fr {
namespace {

FractFile parse_version(const std::string& version, const std::string& body) {
  return parse_fract("# Mandelbulber settings file\n# version " + version +
                         "\n# only modified parameters\n" + body,
                     "test.fract");
}

std::string palette_error(const std::string& line, bool old_palette) {
  const std::string key =
      old_palette ? "mat1_surface_color_palette" : "mat1_surface_color_gradient";
  try {
    const FractFile f = parse_version("2.20", "[main_parameters]\n" + key + " " + line + ";\n");
    if (old_palette)
      mb2_parse_old_palette(f, key, f.main.at(key));
    else
      mb2_parse_gradient(f, key, f.main.at(key));
  } catch (const FractError& e) {
    return e.what();
  }
  return "(no error)";
}

Mb2Gradient gradient(const std::string& text) {
  const FractFile f =
      parse_version("2.20", "[main_parameters]\nmat1_surface_color_gradient " + text + ";\n");
  return mb2_parse_gradient(f, "mat1_surface_color_gradient",
                            f.main.at("mat1_surface_color_gradient"));
}

Mb2Gradient old_palette(const std::string& text) {
  const FractFile f =
      parse_version("2.10", "[main_parameters]\nmat1_surface_color_palette " + text + ";\n");
  return mb2_parse_old_palette(f, "mat1_surface_color_palette",
                               f.main.at("mat1_surface_color_palette"));
}

void expect_rgb(const std::array<double, 3>& c, double r, double g, double b) {
  EXPECT_NEAR(c[0], r, 1e-6);
  EXPECT_NEAR(c[1], g, 1e-6);
  EXPECT_NEAR(c[2], b, 1e-6);
}

// Red at 0, green at 0.5, and red again at 1 (the wrap): linear between.
TEST(Mb2Palette, GradientIsLinearAndWraps) {
  const Mb2Gradient g = gradient("0 ff0000 5000 00ff00");
  EXPECT_EQ(g.colours, 2);
  ASSERT_EQ(g.stops.size(), 3u);
  expect_rgb(mb2_gradient_colour(g, 0.0f), 1, 0, 0);
  expect_rgb(mb2_gradient_colour(g, 0.25f), 0.5, 0.5, 0);
  expect_rgb(mb2_gradient_colour(g, 0.5f), 0, 1, 0);
  expect_rgb(mb2_gradient_colour(g, 0.75f), 0.5, 0.5, 0);
  // Stops out of order are sorted.
  const Mb2Gradient h = gradient("5000 00ff00 0 0000ff");
  expect_rgb(mb2_gradient_colour(h, 0.25f), 0, 0.5, 0.5);
}

// Before 2.19: n colours at int(i / n * 10000); colours without leading zeros; a last token
// shorter than six digits dropped, as Mandelbulber2 drops it.
TEST(Mb2Palette, OldPaletteEvenlySpaced) {
  const Mb2Gradient g = old_palette("ff0000 0000ff 00ff00");
  EXPECT_EQ(g.colours, 3);
  EXPECT_FLOAT_EQ(g.stops[1].position, 0.3333f);
  EXPECT_FLOAT_EQ(g.stops[2].position, 0.6666f);
  // Half way from blue (0.3333) to green (0.6666).
  expect_rgb(mb2_gradient_colour(g, 0.49995f), 0, 0.5, 0.5);
  EXPECT_EQ(old_palette("f0c05 ffffff").colours, 2);  // "ffffff" is whole: kept
  expect_rgb(mb2_gradient_colour(old_palette("f0c05 ffffff"), 0.0f), 15 / 255.0, 12 / 255.0,
             5 / 255.0);
  EXPECT_EQ(old_palette("ffffff f0c05").colours, 1);
  EXPECT_EQ(old_palette("ff0000 00ff00 ").colours, 2);
}

TEST(Mb2Palette, BadPalettesNameFileLineAndKey) {
  EXPECT_NE(palette_error("0 zzzzzz", false).find("test.fract:5: mat1_surface_color_gradient"),
            std::string::npos);
  EXPECT_NE(palette_error("0 zzzzzz", false).find("RRGGBB"), std::string::npos);
  EXPECT_NE(palette_error("0", false).find("pairs"), std::string::npos);
  EXPECT_NE(palette_error("20000 ff0000", false).find("0-10000"), std::string::npos);
  EXPECT_NE(palette_error("ff00gg 00ff00", true).find("mat1_surface_color_palette"),
            std::string::npos);
  EXPECT_NE(palette_error("1234567 00ff00", true).find("RRGGBB"), std::string::npos);
}

TEST(Mb2Palette, SrgbDecoding) {
  EXPECT_DOUBLE_EQ(srgb_to_linear(0), 0);
  EXPECT_DOUBLE_EQ(srgb_to_linear(1), 1);
  EXPECT_NEAR(srgb_to_linear(0.5), 0.21404, 1e-5);  // the sRGB standard's curve
  EXPECT_NEAR(srgb_to_linear(0.04), 0.04 / 12.92, 1e-12);
}

toml::table import_table(const FractFile& f) {
  const Mb2Import imported = import_fract(f, "x");
  EXPECT_TRUE(imported.faithful());
  return toml::parse(imported.preset_toml);
}

// The importer: a 2.20 file's gradient sampled at j / 64; a 2.10 palette of 5 colours with speed
// 2 and offset 1 becomes speed 2 * 10 / 5 and offset 1 / 5; a 2.06 file's `fractal_color false`
// (renamed to mat1_use_colors_from_palette) is one surface colour.
TEST(Mb2Palette, ImporterSamplesTheGradient) {
  const toml::table t = import_table(
      parse_version("2.20",
                    "[main_parameters]\nmat1_surface_color_gradient 0 ff0000 5000 00ff00;\n"
                    "mat1_coloring_speed 3;\nmat1_fractal_coloring_algorithm 2;\n"));
  EXPECT_EQ(t["params"]["colour_mode"].value<std::string>(), "palette");
  EXPECT_EQ(t["params"]["colour_algorithm"].value<std::string>(), "sphere");
  EXPECT_DOUBLE_EQ(t["params"]["colour_speed"].value<double>().value_or(0), 3);
  // palette_16 at 0.25: (0.5, 0.5, 0) as display values, linear in the preset.
  EXPECT_NEAR(t["params"]["palette_16"][0].value<double>().value_or(-1), srgb_to_linear(0.5), 1e-9);
  EXPECT_NEAR(t["params"]["palette_16"][2].value<double>().value_or(-1), 0, 1e-12);
  EXPECT_NEAR(t["params"]["palette_32"][1].value<double>().value_or(-1), 1, 1e-12);

  const toml::table old = import_table(parse_version(
      "2.10",
      "[main_parameters]\nmat1_surface_color_palette 102030 405060 708090 a0b0c0 d0e0f0;\n"
      "mat1_coloring_speed 2;\nmat1_coloring_palette_offset 1;\n"));
  EXPECT_DOUBLE_EQ(old["params"]["colour_speed"].value<double>().value_or(0), 4);
  EXPECT_DOUBLE_EQ(old["params"]["colour_offset"].value<double>().value_or(0), 0.2);
  EXPECT_NEAR(old["params"]["palette_0"][0].value<double>().value_or(-1),
              srgb_to_linear(0x10 / 255.0), 1e-9);

  // A speed beyond the scene's range is clamped, and said.
  const Mb2Import fast =
      import_fract(parse_version("2.20", "[main_parameters]\nmat1_coloring_speed 1e9;\n"), "x");
  EXPECT_DOUBLE_EQ(
      toml::parse(fast.preset_toml)["params"]["colour_speed"].value<double>().value_or(0), 1e6);
  EXPECT_TRUE(std::any_of(fast.notes.begin(), fast.notes.end(), [](const ImportNote& n) {
    return n.item.find("mat1_coloring_speed") != std::string::npos &&
           n.text.find("clamped") != std::string::npos;
  }));

  const toml::table plain = import_table(parse_version(
      "2.06", "[main_parameters]\nfractal_color false;\nmat1_surface_color 8000 0 ffff;\n"));
  EXPECT_EQ(plain["params"]["colour_mode"].value<std::string>(), "surface");
  EXPECT_NEAR(plain["params"]["surface_colour"][0].value<double>().value_or(-1),
              srgb_to_linear(0x8000 / 65535.0), 1e-9);
  EXPECT_NEAR(plain["params"]["surface_colour"][2].value<double>().value_or(-1), 1, 1e-12);
}

// --- The colouring pass on the device ---------------------------------------------------------

class Mb2Colour : public test::Mb2SceneTest {
 protected:
  void SetUp() override {
    Mb2SceneTest::SetUp();
    if (HasFatalFailure()) return;
    choose("colour_mode", "palette");
    // A ramp: sample j is (j / 64, 0, 0), so the albedo's red is the palette position (up to
    // 63 / 64; from there it runs back to sample 0).
    for (int j = 0; j < 64; ++j) set3(("palette_" + std::to_string(j)).c_str(), j / 64.0, 0, 0);
  }
  // The palette position Mandelbulber2 takes for a colour index, as the ramp shows it.
  static double ramp_red(double index, double speed, double offset) {
    double position = std::fmod(std::fabs(index), 248.0 * 256.0) / 2560.0 * speed + offset;
    position -= std::floor(position);
    return position <= 63.0 / 64 ? position : 63.0 / 64 * (64 - 64 * position);
  }
  std::vector<float> red(const std::vector<std::array<float, 3>>& points) {
    const std::vector<float> albedo =
        probe_albedo(test::runtime(), scene->info, values, points, Precision::Double);
    std::vector<float> out;
    for (size_t i = 0; i < points.size(); ++i) out.push_back(albedo[3 * i]);
    return out;
  }
};

struct Z4 {
  double x, y, z, w;
  double length() const { return std::sqrt(x * x + y * y + z * z + w * w); }
  double length3() const { return std::sqrt(x * x + y * y + z * z); }
};

const std::vector<std::array<float, 3>> kPoints = {
    {0.3f, 0.2f, 0.1f},  {1.1f, -0.7f, 0.4f}, {-1.6f, 0.9f, 0.2f},  {0.05f, -0.9f, -0.8f},
    {2.5f, 0.1f, -0.3f}, {0.7f, 0.7f, 0.7f},  {-0.2f, 0.4f, 1.3f},  {1.9f, 1.2f, -1.4f},
    {5.5f, 3.0f, -4.0f}, {-7.0f, 2.0f, 1.5f}, {20.0f, -15.0f, 9.0f}};

// Mandelbulber2's bulb step (latitude by asin, no angle offsets), then c.
void bulb_step(Z4& z, double power, const Z4& c) {
  const double r = z.length();
  const double th = power * std::asin(z.z / r), ph = power * std::atan2(z.y, z.x);
  const double rp = std::pow(r, power);
  z = Z4{rp * std::cos(th) * std::cos(ph) + c.x, rp * std::cos(th) * std::sin(ph) + c.y,
         rp * std::sin(th) + c.z, 0};
}

// A Mandelbox step as Mandelbulber2 colours it: 0.1, 0.2, 0.3 per axis folded, 0.5 for the inner
// sphere, 0.7 for the outer.
void box_step(Z4& z, double& dr, double& colour, const Z4& c) {
  auto fold = [&](double& a, double k) {
    if (std::fabs(a) > 1) {
      a = (a > 0 ? 2 : -2) - a;
      colour += k;
    }
  };
  fold(z.x, 0.1);
  fold(z.y, 0.2);
  fold(z.z, 0.3);
  const double r2 = z.x * z.x + z.y * z.y + z.z * z.z + z.w * z.w;
  double f = 1;
  if (r2 < 0.25) {
    f = 4;
    colour += 0.5;
  } else if (r2 < 1) {
    f = 1 / r2;
    colour += 0.7;
  }
  z = Z4{z.x * f * 2 + c.x, z.y * f * 2 + c.y, z.z * f * 2 + c.z, z.w * f * 2};
  dr = dr * f * 2 + 1;
}

// A Mandelbox alone, standard algorithm: the pass runs on to |z| > 1e15 (or N), and the index is
// 100 fold colour + r colour_r / 1e13. Bounded orbits are chaotic (a rounding doubles each step),
// so they are compared over 18 iterations; orbits that escape early, whose later steps only
// scale, over 60 too, where the 1e15 rule shows in the r term (about 400, against none had they
// stopped at the bailout).
TEST_F(Mb2Colour, MandelboxIndexCountsTheFolds) {
  choose("f1", "mandelbox");
  set("bailout", 100);
  set3("box_colour", 0.1, 0.2, 0.3);
  set("box_colour_sp1", 0.5);
  set("box_colour_sp2", 0.7);
  set("box_colour_r", 2);
  set("colour_speed", 0.37);
  set("colour_offset", 0.1);
  int escaped = 0;
  for (const int n : {18, 60}) {
    set("iterations", n);
    const std::vector<float> got = red(kPoints);
    for (size_t k = 0; k < kPoints.size(); ++k) {
      const Z4 c{kPoints[k][0], kPoints[k][1], kPoints[k][2], 0};
      Z4 z = c;
      double dr = 1, colour = 1;
      bool escapes_early = false;
      for (int i = 0; i < n; ++i) {
        const Z4 last = z;
        box_step(z, dr, colour, c);
        const double r = z.length();
        if (i < 12 && r > 1e3) escapes_early = true;
        const Z4 d{z.x - last.x, z.y - last.y, z.z - last.z, z.w - last.w};
        if (r > 1e15 || d.length() / r < 1e-15) break;
      }
      if (n == 60 && !escapes_early) continue;
      escaped += n == 60;
      const double index = colour * 100 + z.length() * 2 / 1e13;
      EXPECT_NEAR(got[k], ramp_red(index, 0.37, 0.1), 1e-5) << "point " << k << ", N " << n;
    }
  }
  EXPECT_GE(escaped, 2);
}

// The IFS, sphere algorithm: the trap is min ||z - p| - radius| over the iterations (after each
// step, before the bailout test), the index 1000 trap.
TEST_F(Mb2Colour, KifsIndexIsTheTrap) {
  choose("f1", "kifs");
  choose("estimate", "linear");
  choose("colour_algorithm", "sphere");
  set("colour_sphere_radius", 0.8);
  set("iterations", 12);
  set("bailout", 100);
  set("f1_add_c", 0);
  set("kifs_plane0", 1);
  set3("kifs_plane0_direction", 0, 0, 1);
  set("kifs_plane0_distance", 0.1);
  set("colour_speed", 0.05);
  const std::vector<float> got = red(kPoints);
  for (size_t k = 0; k < kPoints.size(); ++k) {
    const Z4 p{kPoints[k][0], kPoints[k][1], kPoints[k][2], 0};
    Z4 z = p;
    double trap = 1000;
    for (int i = 0; i < 12; ++i) {
      if (z.z < 0.1) z.z -= 2 * (z.z - 0.1);     // the plane at z = 0.1
      z = Z4{2 * z.x - 1, 2 * z.y, 2 * z.z, 0};  // scale 2 about (1, 0, 0)
      const Z4 d{z.x - p.x, z.y - p.y, z.z - p.z, 0};
      trap = std::min(trap, std::fabs(d.length3() - 0.8));
      if (z.length() > 100) break;
    }
    EXPECT_NEAR(got[k], ramp_red(trap * 1000, 0.05, 0), 1e-5) << "point " << k;
  }
}

// A hybrid (power-2 bulb, Mandelbox, alternating): the trap |z| is taken after the bulb's steps
// only (a Mandelbox step in the standard algorithm takes none), the bulb's steps end at the
// bailout and the box's at 1e15; the index is 1000 min(trap, 100) + 100 fold colour + 5000
// min(r / dr, 20).
TEST_F(Mb2Colour, HybridIndexByHand) {
  set("hybrid", 1);
  set("bulb_power", 2);
  choose("f2", "mandelbox");
  set3("box_colour", 0.1, 0.2, 0.3);
  set("box_colour_sp1", 0.5);
  set("box_colour_sp2", 0.7);
  set("iterations", 30);
  set("bailout", 10);
  set("colour_speed", 0.011);
  const std::vector<float> got = red(kPoints);
  for (size_t k = 0; k < kPoints.size(); ++k) {
    const Z4 c{kPoints[k][0], kPoints[k][1], kPoints[k][2], 0};
    Z4 z = c;
    double dr = 1, colour = 1, trap = 1000;
    for (int i = 0; i < 30; ++i) {
      const Z4 last = z;
      const bool bulb = i % 2 == 0;
      if (bulb) {
        dr = 2 * z.length() * dr + 1;
        bulb_step(z, 2, c);
      } else {
        box_step(z, dr, colour, c);
      }
      const double r = z.length();
      if (bulb) {
        trap = std::min(trap, z.length3());
        if (r > 10) break;
      } else {
        const Z4 d{z.x - last.x, z.y - last.y, z.z - last.z, z.w - last.w};
        if (r > 1e15 || d.length() / r < 1e-15) break;
      }
    }
    const double index = std::min(trap, 100.0) * 1000 + colour * 100 +
                         std::min(z.length() / std::fabs(dr), 20.0) * 5000;
    EXPECT_NEAR(got[k], ramp_red(index, 0.011, 0), 1e-5) << "point " << k;
  }
}

// The bulb alone: 5000 trap.
TEST_F(Mb2Colour, BulbIndexIsFiveThousandTraps) {
  set("bulb_power", 8);
  set("iterations", 20);
  set("colour_speed", 0.2);
  set("colour_offset", 0.3);
  const std::vector<float> got = red(kPoints);
  for (size_t k = 0; k < kPoints.size(); ++k) {
    const Z4 c{kPoints[k][0], kPoints[k][1], kPoints[k][2], 0};
    Z4 z = c;
    double trap = 1000;
    for (int i = 0; i < 20; ++i) {
      bulb_step(z, 8, c);
      trap = std::min(trap, z.length3());
      if (z.length() > 10) break;
    }
    EXPECT_NEAR(got[k], ramp_red(trap * 5000, 0.2, 0.3), 1e-5) << "point " << k;
  }
}

// The surface mode is the one colour.
TEST_F(Mb2Colour, SurfaceModeIsOneColour) {
  choose("colour_mode", "surface");
  set3("surface_colour", 0.25, 0.5, 0.75);
  const std::vector<float> albedo =
      probe_albedo(test::runtime(), scene->info, values, kPoints, Precision::Double);
  for (size_t k = 0; k < kPoints.size(); ++k) {
    EXPECT_FLOAT_EQ(albedo[3 * k], 0.25f);
    EXPECT_FLOAT_EQ(albedo[3 * k + 2], 0.75f);
  }
}

}  // namespace
}  // namespace fr
