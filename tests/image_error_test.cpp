// The image error measures of bench --explore against answers worked out by hand (constant
// images, a two-pixel stretch) and against SSIM evaluated straight from its definition, window by
// window in double, with no separable filtering.
#include "bench/image_error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace fr {
namespace {

Rgba8Image filled(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  Rgba8Image image{w, h, {}};
  for (int i = 0; i < w * h; ++i) image.rgba.insert(image.rgba.end(), {r, g, b, 255});
  return image;
}

Rgba8Image noise(int w, int h, unsigned seed) {
  std::mt19937 random(seed);
  Rgba8Image image{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
  for (auto& v : image.rgba) v = static_cast<uint8_t>(random() & 0xff);
  return image;
}

// SSIM as the paper defines it, each window's weighted moments summed directly.
double ssim_by_definition(const Rgba8Image& a, const Rgba8Image& b) {
  auto luma = [](const Rgba8Image& im, int x, int y) {
    const uint8_t* p = &im.rgba[(size_t(y) * im.width_px + x) * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  };
  double weights[11][11], total = 0;
  for (int j = 0; j < 11; ++j)
    for (int i = 0; i < 11; ++i)
      total += weights[j][i] = std::exp(-((i - 5.0) * (i - 5.0) + (j - 5.0) * (j - 5.0)) / 4.5);
  const double c1 = 2.55 * 2.55, c2 = 7.65 * 7.65;
  double sum = 0;
  int count = 0;
  for (int y = 0; y + 11 <= a.height_px; ++y)
    for (int x = 0; x + 11 <= a.width_px; ++x) {
      double mx = 0, my = 0;
      for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i) {
          mx += weights[j][i] / total * luma(a, x + i, y + j);
          my += weights[j][i] / total * luma(b, x + i, y + j);
        }
      double vx = 0, vy = 0, cov = 0;
      for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i) {
          const double w = weights[j][i] / total;
          const double dx = luma(a, x + i, y + j) - mx, dy = luma(b, x + i, y + j) - my;
          vx += w * dx * dx;
          vy += w * dy * dy;
          cov += w * dx * dy;
        }
      sum += (2 * mx * my + c1) * (2 * cov + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++count;
    }
  return sum / count;
}

TEST(ImageError, IdenticalImagesHaveNoError) {
  const Rgba8Image a = noise(40, 30, 1);
  EXPECT_EQ(mean_absolute_error(a, a), 0.0);
  EXPECT_NEAR(structural_similarity(a, a), 1.0, 1e-12);
}

TEST(ImageError, ConstantImagesByHand) {
  // Grey 100 against grey 150: |100 - 150| / 255 in every channel; no variance, so SSIM is its
  // luminance term alone, (2 * 100 * 150 + C1) / (100^2 + 150^2 + C1), C1 = 2.55^2.
  const Rgba8Image a = filled(20, 16, 100, 100, 100), b = filled(20, 16, 150, 150, 150);
  EXPECT_NEAR(mean_absolute_error(a, b), 50.0 / 255.0, 1e-15);
  const double c1 = 2.55 * 2.55;
  EXPECT_NEAR(structural_similarity(a, b), (30000 + c1) / (10000 + 22500 + c1), 1e-9);
  // One channel off by 255, the others equal: a third of full scale.
  EXPECT_NEAR(mean_absolute_error(filled(12, 12, 0, 7, 9), filled(12, 12, 255, 7, 9)), 1.0 / 3,
              1e-15);
}

TEST(ImageError, SsimMatchesItsDefinition) {
  const Rgba8Image a = noise(31, 23, 2);
  Rgba8Image b = a;
  std::mt19937 random(3);
  for (auto& v : b.rgba) v = static_cast<uint8_t>(std::clamp(int(v) + int(random() % 61) - 30, 0, 255));
  const double expected = ssim_by_definition(a, b);
  EXPECT_NEAR(structural_similarity(a, b), expected, 1e-9);
  EXPECT_LT(expected, 0.99);  // the noise is visible to the measure
  // Unrelated noise images are structurally unlike: near 0.
  EXPECT_NEAR(structural_similarity(noise(31, 23, 4), noise(31, 23, 5)), 0.0, 0.1);
}

TEST(ImageError, BilinearStretchByHand) {
  // Two pixels, 0 and 255, stretched to four: the centres land at source x = -0.25, 0.25, 0.75
  // and 1.25 (clamped to 0 and 1), so 0, 63.75, 191.25 and 255, rounded.
  const uint8_t two[] = {0, 0, 0, 255, 255, 255, 255, 255};
  const Rgba8Image four = upscale_bilinear(two, 2, 1, 4, 1);
  ASSERT_EQ(four.rgba.size(), 16u);
  EXPECT_EQ(four.rgba[0], 0);
  EXPECT_EQ(four.rgba[4], 64);
  EXPECT_EQ(four.rgba[8], 191);
  EXPECT_EQ(four.rgba[12], 255);
  EXPECT_EQ(four.rgba[3], 255);  // alpha stays
  // The same size is the image itself.
  const Rgba8Image a = noise(9, 7, 6);
  EXPECT_EQ(upscale_bilinear(a.rgba.data(), 9, 7, 9, 7).rgba, a.rgba);
}

TEST(ImageError, MismatchedOrTinyImagesAreRefused) {
  EXPECT_THROW(mean_absolute_error(filled(4, 4, 0, 0, 0), filled(4, 5, 0, 0, 0)),
               std::invalid_argument);
  EXPECT_THROW(structural_similarity(filled(10, 40, 0, 0, 0), filled(10, 40, 0, 0, 0)),
               std::invalid_argument);
  EXPECT_THROW(upscale_bilinear(nullptr, 0, 1, 4, 4), std::invalid_argument);
}

}  // namespace
}  // namespace fr
