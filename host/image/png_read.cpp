#include "image/png_read.hpp"

#include <png.h>

#include <cstring>
#include <fstream>
#include <iterator>

namespace fr {

bool read_png_rgba8(const std::filesystem::path& path, int max_side_px, RgbaImage* image,
                    std::string* error) {
  // Read whole first (the file is small) and decoded from memory: libpng's FILE* entry point
  // does not take a wide path on Windows.
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = path.string() + ": cannot be opened";
    return false;
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
    *error = path.string() + ": not a readable PNG (" + png.message + ")";
    return false;
  }
  if (png.width == 0 || png.height == 0 || png.width > static_cast<png_uint_32>(max_side_px) ||
      png.height > static_cast<png_uint_32>(max_side_px)) {
    *error = path.string() + ": its header says " + std::to_string(png.width) + "x" +
             std::to_string(png.height) + " pixels, outside 1 to " + std::to_string(max_side_px);
    png_image_free(&png);
    return false;
  }
  png.format = PNG_FORMAT_RGBA;
  std::vector<uint8_t> pixels(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr)) {
    *error = path.string() + ": not a readable PNG (" + png.message + ")";
    png_image_free(&png);
    return false;
  }
  image->width_px = static_cast<int>(png.width);
  image->height_px = static_cast<int>(png.height);
  image->rgba8 = std::move(pixels);
  return true;
}

}  // namespace fr
