// Posters: an image rendered in bands of rows and streamed to PNG is the image rendered whole
// (no seams), the file decodes to the right size, and a failure leaves no file.
#include "image/poster.hpp"
#ifdef FRACTALIS_TEST_EXR  // a build with OpenEXR (not the Windows one)
#include "exr_read.hpp"
#include "image/exr_write.hpp"
#endif
#include "plugin/scene_instance.hpp"
#include "test_support.hpp"

namespace fr {
namespace {

// 97 x 61 in float: odd sizes, so packets are partial and the last band is short.
RenderSettings odd_size() {
  RenderSettings s;
  s.width_px = 97;
  s.height_px = 61;
  s.precision = Precision::Float;
  return s;
}

// 97 x 61 (odd sizes: partial packets and a short last band), in bands of 7 rows, against one
// render of the whole: every pixel the same (the kernel computes a band's rays from the whole
// image's pixel grid, bit for bit), and the bands' ray counts add up to the whole's.
TEST(Poster, BandsJoinWithoutSeams) {
  const auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  const RenderSettings s = odd_size();
  Renderer whole_renderer(test::runtime());
  const FrameImage whole = whole_renderer.render(scene->info, state, s, true);

  const auto file = test::fresh_dir("poster") / "bands.png";
  const PosterResult r = render_poster(test::worker(), scene->info, state, s, file, 97 * 7);
  EXPECT_EQ(r.bands, 9);  // 8 bands of 7 rows and one of 5
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(file.string().c_str(), &w, &h, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  ASSERT_EQ(w, 97);
  ASSERT_EQ(h, 61);
  const std::vector<uint8_t> banded(pixels, pixels + static_cast<size_t>(w) * h * 4);
  stbi_image_free(pixels);
  EXPECT_EQ(test::pixels_differing(whole.rgba8, banded, 0), 0u);
  const RayCounts counts = count_rays(whole);
  EXPECT_EQ(r.rays.hit, counts.hit);
  EXPECT_EQ(r.rays.miss, counts.miss);
  EXPECT_EQ(r.rays.hit + r.rays.miss + r.rays.out_of_steps + r.rays.inside, 97u * 61);
}

#ifdef FRACTALIS_TEST_EXR
// An EXR poster in bands of 7 rows holds the passes of the image rendered whole: the same
// channels, and every value of every channel the same.
TEST(Poster, ExrBandsJoinWithoutSeams) {
  const auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  const RenderSettings s = odd_size();
  const FrameImage whole = Renderer(test::runtime()).render(scene->info, state, s, true);
  const auto dir = test::fresh_dir("poster_exr");
  std::string error;
  ASSERT_TRUE(write_exr_atomic(dir / "whole.exr", whole, &error)) << error;
  const PosterResult r =
      render_poster(test::worker(), scene->info, state, s, dir / "bands.exr", 97 * 7);
  EXPECT_EQ(r.bands, 9);
  const test::ExrImage a = test::read_exr(dir / "whole.exr"), b = test::read_exr(dir / "bands.exr");
  ASSERT_EQ(b.width, 97);
  ASSERT_EQ(b.height, 61);
  ASSERT_EQ(a.channel_names, b.channel_names);
  for (const auto& name : a.channel_names) {
    const auto &x = a.channels.at(name), &y = b.channels.at(name);
    size_t off = 0;
    for (size_t i = 0; i < x.size(); ++i) off += !(x[i] == y[i]);  // (+inf == +inf on a miss)
    EXPECT_EQ(off, 0u) << name;
  }
}
#endif

// With a sample count, each band gets every sample: the same as the whole image's accumulation.
TEST(Poster, SamplesApplyPerBand) {
  const auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  RenderSettings s;
  s.width_px = 40;
  s.height_px = 24;
  s.samples = 4;
  s.precision = Precision::Float;
  Renderer whole_renderer(test::runtime());
  const FrameImage whole = whole_renderer.render(scene->info, state, s);
  const auto file = test::fresh_dir("poster_samples") / "aa.png";
  render_poster(test::worker(), scene->info, state, s, file, 40 * 5);
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(file.string().c_str(), &w, &h, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  const std::vector<uint8_t> banded(pixels, pixels + static_cast<size_t>(w) * h * 4);
  stbi_image_free(pixels);
  EXPECT_EQ(test::pixels_differing(whole.rgba8, banded, 1), 0u);
}

// A file that cannot be written fails before rendering; nothing is left in the folder.
TEST(Poster, UnwritableTargetLeavesNothing) {
  const auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  const auto dir = test::fresh_dir("poster_fail");
  RenderSettings s;
  s.width_px = s.height_px = 8;
  EXPECT_THROW(render_poster(test::worker(), scene->info, make_default_state(scene->info), s, dir),
               std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace fr
