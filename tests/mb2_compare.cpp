// mb2_compare — one view rendered by Mandelbulber2 and by Fractalis, compared as surfaces
// (scripts/compare-mandelbulber2.sh runs it for every importable example).
//
//   mb2_compare MB2_ZBUFFER.png FRACTALIS.exr FOV [MIRROR]
//
// Mandelbulber2 2.20 as Debian builds it writes no OpenEXR, so its depth comes as a 16-bit PNG
// normalised per image: 60000 ln(z / zmin) / ln(zmax / zmin), 65535 where the ray missed, zmin and
// zmax not stored. So:
//   - the hit masks compare directly: a pixel mismatches when its hit or miss differs from every
//     pixel of the other image within one pixel (the two pixel grids are half a pixel apart);
//   - the depths compare after fitting ln z = a + b v (v the PNG's value) to Fractalis's depths
//     over the pixels both hit (least absolute deviations, so that a few mismatched pixels do not
//     move the fit): each pixel's difference, in pixel footprints z fov / height, is
//     |z_fractalis - exp(a + b v)| / (z fov / height). A wrong camera or shape shows up in the
//     mask and in the fit's spread; a global scale of depth alone would not.
// Prints one line: "mismatch_percent median_footprints p90_footprints hit_pixels_mb2
// hit_pixels_fr".
#include "exr_read.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

bool read_png16(const char* path, int* w, int* h, std::vector<uint16_t>* out) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path)) return false;
  image.format = PNG_FORMAT_LINEAR_Y;
  out->resize(PNG_IMAGE_SIZE(image) / 2);
  if (!png_image_finish_read(&image, nullptr, out->data(), 0, nullptr)) return false;
  *w = static_cast<int>(image.width);
  *h = static_cast<int>(image.height);
  return true;
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * v.size()));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: mb2_compare MB2_ZBUFFER.png FRACTALIS.exr FOV\n");
    return 2;
  }
  int w = 0, h = 0;
  std::vector<uint16_t> zb;
  if (!read_png16(argv[1], &w, &h, &zb)) {
    std::fprintf(stderr, "mb2_compare: cannot read %s\n", argv[1]);
    return 2;
  }
  fr::test::ExrImage exr;
  try {
    exr = fr::test::read_exr(argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mb2_compare: cannot read %s: %s\n", argv[2], e.what());
    return 2;
  }
  if (exr.width != w || exr.height != h || !exr.channels.count("Z") ||
      !exr.channels.count("mask")) {
    std::fprintf(stderr, "mb2_compare: sizes differ (%dx%d against %dx%d) or no Z/mask\n", w, h,
                 exr.width, exr.height);
    return 2;
  }
  const double fov = std::atof(argv[3]);
  const auto& z = exr.channels["Z"];
  const auto& mask = exr.channels["mask"];
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<char> hit_mb(n), hit_fr(n);
  for (size_t i = 0; i < n; ++i) {
    hit_mb[i] = zb[i] < 65535;
    hit_fr[i] = mask[i] > 0.5f && std::isfinite(z[i]);
  }
  auto any_within_one = [&](const std::vector<char>& img, int x, int y, char value) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int xx = x + dx, yy = y + dy;
        if (xx >= 0 && yy >= 0 && xx < w && yy < h && img[size_t(yy) * w + xx] == value)
          return true;
      }
    return false;
  };
  size_t mismatched = 0, count_mb = 0, count_fr = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      count_mb += hit_mb[i];
      count_fr += hit_fr[i];
      if (hit_mb[i] != hit_fr[i] && !any_within_one(hit_fr, x, y, hit_mb[i]) &&
          !any_within_one(hit_mb, x, y, hit_fr[i]))
        ++mismatched;
    }
  // ln z_fr = a + b v over the pixels both hit: b from the median of pairwise slopes of a sample
  // (Theil-Sen), a from the median residual.
  std::vector<double> v, lz;
  for (size_t i = 0; i < n; ++i)
    if (hit_mb[i] && hit_fr[i] && z[i] > 0) {
      v.push_back(zb[i]);
      lz.push_back(std::log(static_cast<double>(z[i])));
    }
  double median_fp = NAN, p90_fp = NAN;
  if (v.size() >= 8) {
    std::vector<double> slopes;
    const size_t step = std::max<size_t>(1, v.size() / 400);
    for (size_t i = 0; i < v.size(); i += step)
      for (size_t j = i + step; j < v.size(); j += step * 7)
        if (std::fabs(v[j] - v[i]) > 50) slopes.push_back((lz[j] - lz[i]) / (v[j] - v[i]));
    const double b = slopes.empty() ? 0 : median(slopes);
    std::vector<double> residual(v.size());
    for (size_t i = 0; i < v.size(); ++i) residual[i] = lz[i] - b * v[i];
    const double a = median(residual);
    std::vector<double> fp(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
      const double zf = std::exp(lz[i]), zm = std::exp(a + b * v[i]);
      fp[i] = std::fabs(zf - zm) / (zf * fov / h);
    }
    median_fp = median(fp);
    p90_fp = quantile(fp, 0.9);
  }
  std::printf("%.3f %.3f %.3f %zu %zu\n", 100.0 * mismatched / n, median_fp, p90_fp, count_mb,
              count_fr);
  return 0;
}
