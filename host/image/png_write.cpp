#include "image/png_write.hpp"

#include "io/atomic_file.hpp"

#include <stb_image_write.h>

namespace fr {
namespace {

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

}  // namespace

bool write_png_atomic(const std::filesystem::path& path, int w, int h,
                      const std::vector<uint8_t>& rgba8, std::string* error) {
  if (w <= 0 || h <= 0 || rgba8.size() != static_cast<size_t>(w) * h * 4) {
    *error = "cannot write " + path.string() + ": image size does not match its pixels";
    return false;
  }
  std::string png;
  if (!stbi_write_png_to_func(append_bytes, &png, w, h, 4, rgba8.data(), w * 4)) {
    *error = "cannot write " + path.string() + ": PNG encoding failed";
    return false;
  }
  return write_file_atomic(path, png, error);
}

}  // namespace fr
