// environment_image.hpp — an equirectangular HDR panorama for the sky (render.environment): a
// Radiance .hdr file (read with stb_image) or an OpenEXR file (read with OpenEXR), as linear RGB
// floats. Every way a file can be wrong is an error that names the file and what is wrong with
// it; nothing is guessed (stb_image itself fills a truncated .hdr with black, so the reader
// watches for reads past the file's end).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fr {

struct EnvironmentImage {
  int width_px = 0, height_px = 0;
  std::vector<float> rgb;  // linear radiance, 3 floats a pixel, rows top (zenith) to bottom
};

// The largest panorama accepted: 8192 x 4096 (400 MB as floats, on the device too).
constexpr int kMaxEnvironmentWidthPx = 8192;

// Reads `path`: false with *error set ("cannot open ...", "... is not a Radiance HDR or OpenEXR
// image", "... is truncated", "... is 1920x1080: an equirectangular panorama is twice as wide as
// it is high", a negative or non-finite pixel, a size over kMaxEnvironmentWidthPx) when it
// cannot be used.
bool read_environment_image(const std::filesystem::path& path, EnvironmentImage* image,
                            std::string* error);

// OpenEXR's part (image/exr_read.cpp; exr_read_missing.cpp refuses with the reason where the
// build has no OpenEXR): the file's RGB, any size; false with *error on any failure.
bool read_exr_rgb(const std::filesystem::path& path, int max_width_px, EnvironmentImage* image,
                  std::string* error);

}  // namespace fr
