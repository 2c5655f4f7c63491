// The Mandelbulb at 128x128: lane widths agree, float agrees with the double reference within a
// stated tolerance, and no pixel is NaN or infinite — at the default view and at the extremes
// of the parameter range.
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace fr {
namespace {

class MandelbulbRender : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = test::mandelbulb();
    ASSERT_TRUE(scene);
    state = make_default_state(scene->info);
    std::string error;
    instance = SceneInstance::create(scene, &error);
    ASSERT_TRUE(instance) << error;
  }
  FrameImage render(int lanes, Precision precision) {
    std::string error;
    EXPECT_TRUE(instance->update(state, 0, &error)) << error;
    RenderSettings s;
    s.width_px = 128;
    s.height_px = 128;
    s.lanes = lanes;
    s.precision = precision;
    return Renderer(test::runtime()).render(scene->info, state, s, true);
  }
  std::shared_ptr<const LoadedScene> scene;
  std::unique_ptr<SceneInstance> instance;
  SceneState state;
};

// Fraction of pixels where some channel differs by more than `tolerance` (of 255).
double fraction_differing(const FrameImage& a, const FrameImage& b, int tolerance) {
  return double(test::pixels_differing(a.rgba8, b.rgba8, tolerance)) / double(a.rgba8.size() / 4);
}

size_t non_finite(const FrameImage& img) {
  size_t n = 0;
  for (float v : img.linear_rgba) n += std::isfinite(v) ? 0 : 1;
  return n;
}

double hit_fraction(const FrameImage& img) {
  size_t n = 0;
  for (float d : img.depth) n += std::isfinite(d) ? 1 : 0;
  return double(n) / double(img.depth.size());
}

TEST_F(MandelbulbRender, LaneWidthsAgree) {
  const FrameImage one = render(1, Precision::Float);
  const FrameImage sixteen = render(16, Precision::Float);
  EXPECT_EQ(non_finite(one), 0u);
  EXPECT_EQ(non_finite(sixteen), 0u);
  EXPECT_GT(hit_fraction(one), 0.1) << "the default view shows the bulb";
  const double differing = fraction_differing(one, sixteen, 2);
  RecordProperty("lanes_1_vs_16_fraction_over_2", std::to_string(differing));
  EXPECT_LE(differing, 0.005) << "more than 0.5% of pixels differ by more than 2/255";
  // The wide packets (kernels/wide_lanes.cl) run each lane through the same operations as 16.
  for (int lanes : {32, 64}) {
    const FrameImage wide = render(lanes, Precision::Float);
    EXPECT_EQ(wide.lanes, lanes);
    EXPECT_EQ(fraction_differing(sixteen, wide, 0), 0.0) << lanes << " lanes against 16";
  }
}

// Float against the double reference. The surface of a fractal is chaotic at the scale of the hit
// threshold, so single pixels may flip between hit and miss or land on another facet. Stated
// tolerance: at most 0.5% of pixels differ by more than 2/255, at most 0.2% of hit masks differ,
// and where both hit, the median relative depth difference is below 1e-4. (Measured at the
// default view: 0, 0 and about 1e-6.)
TEST_F(MandelbulbRender, FloatMatchesDoubleReference) {
  const FrameImage f = render(16, Precision::Float);
  const FrameImage d = render(16, Precision::Double);
  EXPECT_EQ(non_finite(d), 0u);
  const double differing = fraction_differing(f, d, 2);
  size_t mask_diff = 0;
  for (size_t i = 0; i < f.depth.size(); ++i)
    mask_diff += std::isfinite(f.depth[i]) != std::isfinite(d.depth[i]);
  const double mask_fraction = double(mask_diff) / double(f.depth.size());
  std::vector<double> relative;
  for (size_t i = 0; i < f.depth.size(); ++i)
    if (std::isfinite(f.depth[i]) && std::isfinite(d.depth[i]))
      relative.push_back(std::abs(f.depth[i] - d.depth[i]) / d.depth[i]);
  ASSERT_FALSE(relative.empty());
  std::nth_element(relative.begin(), relative.begin() + relative.size() / 2, relative.end());
  const double median_relative = relative[relative.size() / 2];
  RecordProperty("float_vs_double_fraction_over_2", std::to_string(differing));
  RecordProperty("float_vs_double_mask_fraction", std::to_string(mask_fraction));
  RecordProperty("float_vs_double_median_relative_depth", std::to_string(median_relative));
  EXPECT_LE(differing, 0.005);
  EXPECT_LE(mask_fraction, 0.002);
  EXPECT_LT(median_relative, 1e-4);
}

TEST_F(MandelbulbRender, ExtremeParametersStayFinite) {
  struct Case {
    double power, bailout;
    int iterations;
  };
  for (Case c : {Case{2, 12, 64}, Case{16, 1.5, 30}, Case{16, 12, 1}}) {
    state.params[scene->info.find_param("power")].v[0] = c.power;
    state.params[scene->info.find_param("bailout")].v[0] = c.bailout;
    state.params[scene->info.find_param("iterations")].v[0] = c.iterations;
    const FrameImage img = render(16, Precision::Float);
    EXPECT_EQ(non_finite(img), 0u) << "power " << c.power << " bailout " << c.bailout;
  }
}

}  // namespace
}  // namespace fr
