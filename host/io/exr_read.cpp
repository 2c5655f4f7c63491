#include "io/environment_image.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <exception>

namespace fr {

bool read_exr_rgb(const std::filesystem::path& path, int max_width_px, EnvironmentImage* image,
                  std::string* error) {
  try {
    Imf::InputFile file(path.string().c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
    if (w <= 0 || h <= 0 || w > max_width_px || h > max_width_px) {
      *error = path.string() + " is " + std::to_string(w) + "x" + std::to_string(h) +
               ": the largest panorama read is " + std::to_string(max_width_px) + "x" +
               std::to_string(max_width_px / 2) + " (scale it down first)";
      return false;
    }
    // R, G and B; or Y alone (a grey panorama). A missing channel is not read as black.
    const Imf::ChannelList& channels = file.header().channels();
    const bool rgb =
        channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    if (!rgb && !channels.findChannel("Y")) {
      *error = path.string() + " has neither R, G and B channels nor a Y channel";
      return false;
    }
    image->width_px = static_cast<int>(w);
    image->height_px = static_cast<int>(h);
    image->rgb.assign(static_cast<size_t>(w * h * 3), 0.0f);
    // Slices are addressed from the data window's origin (OpenEXR's convention); every channel
    // is converted to float, so a half file's values and a float file's beyond half's range
    // arrive as they are.
    const size_t x_stride = 3 * sizeof(float), y_stride = x_stride * static_cast<size_t>(w);
    char* origin =
        reinterpret_cast<char*>(image->rgb.data()) -
        static_cast<std::ptrdiff_t>(window.min.x) * static_cast<std::ptrdiff_t>(x_stride) -
        static_cast<std::ptrdiff_t>(window.min.y) * static_cast<std::ptrdiff_t>(y_stride);
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < (rgb ? 3 : 1); ++c)
      frame.insert(rgb ? names[c] : "Y",
                   Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), x_stride, y_stride));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    if (!rgb)
      for (size_t i = 0; i < image->rgb.size(); i += 3)
        image->rgb[i + 1] = image->rgb[i + 2] = image->rgb[i];
    return true;
  } catch (const std::exception& e) {
    *error = "cannot read " + path.string() + " as OpenEXR: " + e.what();
    *image = EnvironmentImage{};
    return false;
  }
}

}  // namespace fr
