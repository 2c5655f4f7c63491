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
  // Encoded whole in memory first: the file is open only for as long as writing the bytes takes
  // (a rank of an MPI job killed while encoding leaves no temporary file in the folder).
  std::string png;
  try {
    PngStream encoder(png, w, h);  // one PNG encoder for every image, whole or in bands
    encoder.write_rows(rgba8.data(), h);
    encoder.finish();
  } catch (const std::exception& e) {
    *error = "cannot write " + path.string() + ": " + e.what();
    return false;
  }
  return write_file_atomic(path, png, error);
}

}  // namespace fr
