// The display image (kernels/post.cl: exposure, ACES filmic fit, sRGB encoding with its own
// log2/exp2) against the same formulas in double on the host, pixel by pixel, for a rendered
// frame's linear values and for a ramp that covers the sRGB curve's whole range.
#include "display_reference.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <cmath>
#include <set>

namespace fr {
namespace {

using test::display_level;

void expect_display_matches(const FrameImage& img, double exposure, const std::string& what) {
  ASSERT_EQ(img.linear_rgba.size(), img.rgba8.size());
  size_t off_by_one = 0, worse = 0;
  for (size_t i = 0; i < img.rgba8.size(); ++i) {
    if (i % 4 == 3) {
      EXPECT_EQ(img.rgba8[i], 255);
      continue;
    }
    const int diff = std::abs(int(img.rgba8[i]) - display_level(img.linear_rgba[i], exposure));
    off_by_one += diff == 1;
    worse += diff > 1;
  }
  EXPECT_EQ(worse, 0u) << what;
  // Float rounding of the formulas may move a value that lies on a level's edge.
  EXPECT_LE(off_by_one, img.rgba8.size() / 1000) << what;
}

TEST(Post, RenderedFrameMatchesTheFormulas) {
  auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  RenderSettings s;
  s.width_px = 96;
  s.height_px = 64;
  for (float exposure : {1.0f, 0.05f, 4.0f}) {
    s.exposure = exposure;
    const FrameImage img =
        Renderer(test::runtime()).render(scene->info, make_default_state(scene->info), s, true);
    expect_display_matches(img, exposure, "exposure " + std::to_string(exposure));
  }
}

// A sky that fills the view with every brightness: a camera looking away from the bulb sees only
// the sky gradient; exposures from 1e-4 to 1e3 walk its colours over the whole curve, the linear
// segment near black included.
TEST(Post, WholeCurve) {
  auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  state.camera.eye[0] = 0;
  state.camera.eye[1] = 0;
  state.camera.eye[2] = 3;
  state.camera.target[0] = 0;
  state.camera.target[1] = 0;
  state.camera.target[2] = 10;
  RenderSettings s;
  s.width_px = 64;
  s.height_px = 64;
  std::set<int> levels;
  for (double exposure = 1e-4; exposure < 1e3; exposure *= 1.5) {
    s.exposure = static_cast<float>(exposure);
    const FrameImage img = Renderer(test::runtime()).render(scene->info, state, s, true);
    expect_display_matches(img, s.exposure, "exposure " + std::to_string(exposure));
    for (size_t i = 0; i < img.rgba8.size(); ++i)
      if (i % 4 != 3) levels.insert(img.rgba8[i]);
  }
  EXPECT_GE(levels.size(), 200u) << "the ramp must cover most of the 8-bit levels";
}

}  // namespace
}  // namespace fr
