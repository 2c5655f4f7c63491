// image_error.hpp — how far a displayed picture is from a reference, as a viewer judges it: the
// mean absolute error of the 8-bit colours and the structural similarity index (SSIM: Wang,
// Bovik, Sheikh and Simoncelli, "Image quality assessment: from error visibility to structural
// similarity", IEEE TIP 2004), and the bilinear stretch a window applies to a smaller frame (what
// the explorer shows while it renders below full resolution).
#pragma once

#include <cstdint>
#include <vector>

namespace fr {

struct Rgba8Image {
  int width_px = 0;
  int height_px = 0;
  std::vector<uint8_t> rgba;  // width x height x 4, rows top first
};

// `rgba` (width x height) stretched to out_width x out_height by bilinear filtering with pixel
// centres aligned and edges clamped, as a GPU's linear texture filter does (SDL's "linear" scale
// quality, which the explorer's window uses).
Rgba8Image upscale_bilinear(const uint8_t* rgba, int width_px, int height_px, int out_width_px,
                            int out_height_px);

// The mean over every pixel's R, G and B of |a - b|, in units of full scale (0 to 1). Throws
// std::invalid_argument when the sizes differ.
double mean_absolute_error(const Rgba8Image& a, const Rgba8Image& b);

// The mean SSIM over the images' luma (Rec. 709 weights of the 8-bit values, dynamic range 255),
// with the paper's 11x11 Gaussian window (sigma 1.5), C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2,
// over every position where the window fits. 1 for identical images. Throws
// std::invalid_argument when the sizes differ or an image is smaller than the window.
double structural_similarity(const Rgba8Image& a, const Rgba8Image& b);
constexpr int kSsimWindowPx = 11;  // the window's side

}  // namespace fr
