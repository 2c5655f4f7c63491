// png_write.hpp — writing an 8-bit RGBA image as PNG without ever leaving a half-written file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fr {

// Encodes to PNG in memory (image/png_stream.hpp: one encoder for whole images and posters'
// bands), writes a temporary file beside `path`, flushes it to disk and renames it over `path`. On
// failure returns false, sets *error (naming the path and the reason) and leaves any existing file
// at `path` untouched.
bool write_png_atomic(const std::filesystem::path& path, int width_px, int height_px,
                      const std::vector<uint8_t>& rgba8, std::string* error);

}  // namespace fr
