// png_read.hpp — reading a PNG file back as 8-bit RGBA (the explorer's thumbnail cache), with
// libpng's simplified API: any PNG colour type and depth comes out as RGBA.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fr {

struct RgbaImage {
  int width_px = 0, height_px = 0;
  std::vector<uint8_t> rgba8;  // rows top to bottom
};

// Reads `path`. A file that is missing, not a PNG, truncated, or larger than `max_side_px` on a
// side (a hostile header asking for gigabytes is refused before any pixel is read) returns false
// and sets *error, naming the file and what was wrong.
bool read_png_rgba8(const std::filesystem::path& path, int max_side_px, RgbaImage* image,
                    std::string* error);

}  // namespace fr
