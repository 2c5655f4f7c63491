// kernels/wide_lanes.cl's overloads against OpenCL's own 16-lane built-ins. An overloaded
// built-in, on the same per-lane inputs, must give at 32 and 64 lanes the very bits the
// implementation's float16 / double16 built-in gives at 16: the wide overload only takes the
// 16-lane parts, calls that built-in and joins the results, so any difference is a part taken
// from the wrong lanes, joined in the wrong order, or an argument passed to the wrong slot.
// (All of them in one kernel took PoCL over ten minutes to build at 64 lanes.)
// (Mutations tried: FR_PART2's indices shifted by one; FR_JOIN16's halves swapped; clamp's
// scalar bounds passed in the other order. Each fails here.)
#include "render/de_probe.hpp"
#include "test_support.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fr {
namespace {

// Expressions in x and y (per lane, in (-2, 2)): one built-in of each shape wide_lanes.cl
// overloads by a macro (the macro writes the same name it is given, so one of a shape tests the
// parts and joins of all), and every one written out by hand.
std::vector<std::string> expressions(bool in_double) {
  std::vector<std::string> e = {
      "sqrt(fabs(x))",                              // FR_WIDE_V
      "atan2(x, y)",                                // FR_WIDE_VV
      "fmax(x, (scalar_t)0.25)",                    // FR_WIDE_VS
      "fma(x, y, x * y)",                           // FR_WIDE_VVV
      "mask_to_real(isnan(log(x)))",                // FR_WIDE_TEST
      "mask_to_real(isless(round(x), y))",          // FR_WIDE_TEST2
      "step((scalar_t)0.25, x)",                    // by hand from here on
      "clamp(x, (scalar_t)-0.5, (scalar_t)0.75)",
      "mix(x, y, (scalar_t)0.25)",
      "smoothstep((scalar_t)-0.5, (scalar_t)0.75, x)",
      "select(x, y, x < y)",
      "lane_select(x < y, x * 2, y * 3)",
      "fract_sum(x * 5)",
      "modf_sum(x * 5)",
      "sincos_sum(x * 5)",
      "uint_to_real(real_to_uint(fabs(x) * 1000))",
  };
  if (!in_double) e.push_back("native_sin(x * 3)");
  return e;
}

// One DE that evaluates every expression at (p.x, p.y) and returns the one p.z numbers.
SceneInfo probe_scene(const std::vector<std::string>& exprs) {
  std::ostringstream src;
  src << "inline real_t fract_sum(real_t x) { real_t w; real_t f = fract(x, &w); return f + 3 * w; }\n"
      << "inline real_t modf_sum(real_t x) { real_t w; real_t f = modf(x, &w); return f + 3 * w; }\n"
      << "inline real_t sincos_sum(real_t x) { real_t c; real_t s = sincos(x, &c); return s + 3 * c; }\n"
      << "real_t scene_de(vec3_t p, __constant const scene_params_t* params) {\n"
      << "  const real_t x = p.x, y = p.y;\n"
      << "  real_t r = (real_t)0;\n";
  for (size_t k = 0; k < exprs.size(); ++k)
    src << "  r = lane_select(p.z == (real_t)" << k << ", " << exprs[k] << ", r);\n";
  src << "  return r;\n}\n";
  SceneInfo info;
  info.id = "wide_lanes_probe";
  info.de_source_name = "probe.cl";
  info.de_source = src.str();
  return info;
}

bool same_bits(float a, float b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  uint32_t ua, ub;
  std::memcpy(&ua, &a, 4);
  std::memcpy(&ub, &b, 4);
  return ua == ub;
}

void check_widths(Precision precision) {
  const std::vector<std::string> exprs = expressions(precision != Precision::Float);
  const SceneInfo info = probe_scene(exprs);
  // For each expression, 128 points with different x and y in every lane (and 0 among them).
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-2, 2);
  std::vector<std::array<float, 3>> points;
  for (size_t k = 0; k < exprs.size(); ++k)
    for (int i = 0; i < 128; ++i)
      points.push_back({i == 5 ? 0.0f : coordinate(random), i == 9 ? 0.0f : coordinate(random),
                        static_cast<float>(k)});
  const std::vector<float> narrow = probe_de(test::runtime(), info, {}, points, 16, precision);
  ASSERT_EQ(narrow.size(), points.size());
  for (int lanes : {32, 64}) {
    const std::vector<float> wide = probe_de(test::runtime(), info, {}, points, lanes, precision);
    ASSERT_EQ(wide.size(), points.size());
    int reported = 0;
    for (size_t i = 0; i < points.size(); ++i)
      if (!same_bits(wide[i], narrow[i]) && reported++ < 20)
        ADD_FAILURE() << exprs[static_cast<size_t>(points[i][2])] << " at x = " << points[i][0]
                      << ", y = " << points[i][1] << " (point " << i << ", lane "
                      << i % static_cast<size_t>(lanes) << " of " << lanes << "): " << wide[i]
                      << " against " << narrow[i] << " at 16 lanes";
  }
}

TEST(WideLanes, OverloadsMatchTheSixteenLaneBuiltInsInFloat) { check_widths(Precision::Float); }

TEST(WideLanes, OverloadsMatchTheSixteenLaneBuiltInsInDouble) {
  if (!test::runtime().device().has_fp64) GTEST_SKIP() << "the device has no double";
  check_widths(Precision::Double);
}

}  // namespace
}  // namespace fr
