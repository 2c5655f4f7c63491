#include "bench/image_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace fr {
namespace {

constexpr int kWindow = kSsimWindowPx;
constexpr double kSigma = 1.5;

void require_same_size(const Rgba8Image& a, const Rgba8Image& b) {
  if (a.width_px != b.width_px || a.height_px != b.height_px || a.rgba.size() != b.rgba.size() ||
      a.rgba.size() != static_cast<size_t>(a.width_px) * a.height_px * 4)
    throw std::invalid_argument("image error: the images differ in size (" +
                                std::to_string(a.width_px) + "x" + std::to_string(a.height_px) +
                                " against " + std::to_string(b.width_px) + "x" +
                                std::to_string(b.height_px) + ")");
}

std::vector<double> luma(const Rgba8Image& image) {
  std::vector<double> y(static_cast<size_t>(image.width_px) * image.height_px);
  for (size_t i = 0; i < y.size(); ++i) {
    const uint8_t* p = &image.rgba[i * 4];
    y[i] = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  }
  return y;
}

// `values` (width x height) filtered by the normalised Gaussian window, at every position where
// it fits: (width - 10) x (height - 10), separably (rows, then columns).
std::vector<double> windowed_mean(const std::vector<double>& values, int width, int height,
                                  const std::array<double, kWindow>& weights) {
  const int out_w = width - kWindow + 1, out_h = height - kWindow + 1;
  std::vector<double> rows(static_cast<size_t>(out_w) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < out_w; ++x) {
      double sum = 0;
      for (int k = 0; k < kWindow; ++k) sum += weights[k] * values[size_t(y) * width + x + k];
      rows[size_t(y) * out_w + x] = sum;
    }
  std::vector<double> out(static_cast<size_t>(out_w) * out_h);
  for (int y = 0; y < out_h; ++y)
    for (int x = 0; x < out_w; ++x) {
      double sum = 0;
      for (int k = 0; k < kWindow; ++k) sum += weights[k] * rows[size_t(y + k) * out_w + x];
      out[size_t(y) * out_w + x] = sum;
    }
  return out;
}

}  // namespace

Rgba8Image upscale_bilinear(const uint8_t* rgba, int width_px, int height_px, int out_width_px,
                            int out_height_px) {
  if (width_px < 1 || height_px < 1 || out_width_px < 1 || out_height_px < 1)
    throw std::invalid_argument("upscale_bilinear: an empty image");
  Rgba8Image out;
  out.width_px = out_width_px;
  out.height_px = out_height_px;
  out.rgba.resize(static_cast<size_t>(out_width_px) * out_height_px * 4);
  // The source position of each destination pixel's centre, and its two neighbours' weights.
  auto source = [](int i, int n, int out_n, int& i0, int& i1, double& t) {
    const double s = std::clamp((i + 0.5) * n / out_n - 0.5, 0.0, double(n - 1));
    i0 = static_cast<int>(s);
    i1 = std::min(i0 + 1, n - 1);
    t = s - i0;
  };
  for (int y = 0; y < out_height_px; ++y) {
    int y0, y1;
    double ty;
    source(y, height_px, out_height_px, y0, y1, ty);
    for (int x = 0; x < out_width_px; ++x) {
      int x0, x1;
      double tx;
      source(x, width_px, out_width_px, x0, x1, tx);
      for (int c = 0; c < 4; ++c) {
        auto at = [&](int sx, int sy) { return double(rgba[(size_t(sy) * width_px + sx) * 4 + c]); };
        const double top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * tx;
        const double bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * tx;
        out.rgba[(size_t(y) * out_width_px + x) * 4 + c] =
            static_cast<uint8_t>(std::lround(top + (bottom - top) * ty));
      }
    }
  }
  return out;
}

double mean_absolute_error(const Rgba8Image& a, const Rgba8Image& b) {
  require_same_size(a, b);
  if (a.rgba.empty()) return 0;
  uint64_t sum = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
  return double(sum) / (255.0 * 3.0 * double(a.rgba.size() / 4));
}

double structural_similarity(const Rgba8Image& a, const Rgba8Image& b) {
  require_same_size(a, b);
  const int w = a.width_px, h = a.height_px;
  if (w < kWindow || h < kWindow)
    throw std::invalid_argument("structural similarity: an image smaller than the 11x11 window (" +
                                std::to_string(w) + "x" + std::to_string(h) + ")");
  std::array<double, kWindow> weights;
  double total = 0;
  for (int k = 0; k < kWindow; ++k) {
    const double d = k - (kWindow - 1) / 2.0;
    weights[k] = std::exp(-d * d / (2 * kSigma * kSigma));
    total += weights[k];
  }
  for (double& weight : weights) weight /= total;

  const std::vector<double> x = luma(a), y = luma(b);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const auto mx = windowed_mean(x, w, h, weights), my = windowed_mean(y, w, h, weights);
  const auto mxx = windowed_mean(xx, w, h, weights), myy = windowed_mean(yy, w, h, weights);
  const auto mxy = windowed_mean(xy, w, h, weights);
  const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  double sum = 0;
  for (size_t i = 0; i < mx.size(); ++i) {
    const double vx = mxx[i] - mx[i] * mx[i], vy = myy[i] - my[i] * my[i];
    const double cov = mxy[i] - mx[i] * my[i];
    sum += ((2 * mx[i] * my[i] + c1) * (2 * cov + c2)) /
           ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
  }
  return sum / double(mx.size());
}

}  // namespace fr
