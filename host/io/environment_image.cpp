#include "io/environment_image.hpp"

#include <stb_image.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>

namespace fr {
namespace {

// The smallest non-zero value of a Radiance pixel whose exponent byte is 255 (about 6.6e35), as
// stb_image decodes it: a padding byte read as an exponent gives at least this.
const float kPaddingExponentValue = std::ldexp(1.0f, 255 - 136);

// stb_image reads a Radiance file that ends early as if the missing pixels were black (its reader
// returns zeros past the end) and reports success. So the file is decoded with as many 0xFF bytes
// after it as its pixels could need: a complete file never reads them, a truncated one reads them
// as exponents of 255 (values of 6.6e35 and more, which no real panorama holds; a black pixel
// stays black, rightly) or as a broken run-length code.
bool read_radiance_hdr(const std::filesystem::path& path, std::vector<char>& bytes,
                       EnvironmentImage* image, std::string* error) {
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                             static_cast<int>(bytes.size()), &w, &h, &channels)) {
    *error =
        path.string() + " is not a readable Radiance HDR image (" + stbi_failure_reason() + ")";
    return false;
  }
  if (w <= 0 || h <= 0 || w > kMaxEnvironmentWidthPx || h > kMaxEnvironmentWidthPx) {
    *error = path.string() + " is " + std::to_string(w) + "x" + std::to_string(h) +
             ": the largest panorama read is " + std::to_string(kMaxEnvironmentWidthPx) + "x" +
             std::to_string(kMaxEnvironmentWidthPx / 2) + " (scale it down first)";
    return false;
  }
  const size_t file_bytes = bytes.size();
  bytes.resize(file_bytes + 4 * (static_cast<size_t>(w) + 1) * (static_cast<size_t>(h) + 1) + 256,
               static_cast<char>(0xFF));
  int rw = 0, rh = 0;
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                             static_cast<int>(bytes.size()), &rw, &rh, &channels, 3),
      &stbi_image_free);
  const std::string truncated = path.string() + " is truncated: its " + std::to_string(w) + "x" +
                                std::to_string(h) + " pixels need more than its " +
                                std::to_string(file_bytes) + " bytes";
  if (!pixels) {
    // A run-length code broken by the padding: the file ended inside it.
    *error = std::string(stbi_failure_reason()) == "corrupt"
                 ? truncated + " (or its run-length code is corrupt)"
                 : path.string() + " is not a readable Radiance HDR image (" +
                       stbi_failure_reason() + ")";
    return false;
  }
  const size_t values = static_cast<size_t>(w) * h * 3;
  for (size_t i = 0; i < values; ++i)
    if (pixels.get()[i] >= kPaddingExponentValue) {
      *error = truncated;
      return false;
    }
  image->width_px = w;
  image->height_px = h;
  image->rgb.assign(pixels.get(), pixels.get() + values);
  return true;
}

}  // namespace

bool read_environment_image(const std::filesystem::path& path, EnvironmentImage* image,
                            std::string* error) {
  *image = EnvironmentImage{};
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    *error = "cannot open " + path.string() + ": " +
             (std::filesystem::exists(path, ec) ? "not a file" : "no such file");
    return false;
  }
  // The largest acceptable file: an uncompressed 8192 x 4096 RGBE .hdr is 128 MiB, an
  // uncompressed float RGBA .exr 512 MiB.
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > (size_t{1} << 30)) {
    *error = "cannot read " + path.string() + ": " + (ec ? ec.message() : "larger than 1 GiB");
    return false;
  }
  std::vector<char> bytes;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      *error = "cannot open " + path.string() + ": " + std::strerror(errno);
      return false;
    }
    bytes.resize(size);
    if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) {
      *error = "cannot read " + path.string();
      return false;
    }
  }
  static const char kRadiance[] = "#?RADIANCE", kRgbe[] = "#?RGBE";
  static const unsigned char kExrMagic[] = {0x76, 0x2f, 0x31, 0x01};
  const auto starts_with = [&](const void* magic, size_t n) {
    return bytes.size() >= n && std::memcmp(bytes.data(), magic, n) == 0;
  };
  bool ok = false;
  if (starts_with(kRadiance, sizeof kRadiance - 1) || starts_with(kRgbe, sizeof kRgbe - 1)) {
    ok = read_radiance_hdr(path, bytes, image, error);
  } else if (starts_with(kExrMagic, sizeof kExrMagic)) {
    bytes = {};
    ok = read_exr_rgb(path, kMaxEnvironmentWidthPx, image, error);
  } else {
    *error = path.string() + " is not a Radiance HDR (.hdr) or OpenEXR (.exr) image";
    return false;
  }
  if (!ok) return false;
  // Equirectangular: 360 degrees across, 180 down. A photograph or a cube map is not one.
  const int w = image->width_px, h = image->height_px;
  if (std::abs(w - 2 * h) > std::max(2, w / 100)) {
    *error = path.string() + " is " + std::to_string(w) + "x" + std::to_string(h) +
             ": an equirectangular panorama is twice as wide as it is high";
    *image = EnvironmentImage{};
    return false;
  }
  for (size_t i = 0; i < image->rgb.size(); ++i) {
    const float v = image->rgb[i];
    if (!(v >= 0.0f) || !std::isfinite(v)) {
      const size_t pixel = i / 3;
      char where[128];
      std::snprintf(where, sizeof where, "pixel (%zu, %zu) channel %c is %g", pixel % w, pixel / w,
                    "RGB"[i % 3], static_cast<double>(v));
      *error = path.string() + ": " + where + ": radiance must be finite and not negative";
      *image = EnvironmentImage{};
      return false;
    }
  }
  return true;
}

}  // namespace fr
