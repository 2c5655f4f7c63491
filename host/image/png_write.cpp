#include "image/png_write.hpp"

#include "image/png_stream.hpp"
#include "io/atomic_file.hpp"

#include <stdexcept>

namespace fr {

bool write_png_atomic(const std::filesystem::path& path, int w, int h,
                      const std::vector<uint8_t>& rgba8, std::string* error) {
  if (w <= 0 || h <= 0 || rgba8.size() != static_cast<size_t>(w) * h * 4) {
    *error = "cannot write " + path.string() + ": image size does not match its pixels";
    return false;
  }
  auto out = OutputFile::open(path, error);
  if (!out) return false;
  try {
    PngStream png(*out, w, h);  // one PNG encoder for every image, whole or in bands
    png.write_rows(rgba8.data(), h);
    png.finish();
    return true;
  } catch (const std::exception& e) {
    const std::string what = e.what();
    *error = what.rfind("cannot write " + path.string(), 0) == 0
                 ? what
                 : "cannot write " + path.string() + ": " + what;
    return false;
  }
}

}  // namespace fr
