// png_stream.hpp — a PNG written a band of rows at a time (libpng), for images too large to hold
// whole: a 24000 x 13500 poster is 1.3 GB of RGBA8, its bands a few MB each. The bytes go to an
// OutputFile (io/atomic_file.hpp): the file appears whole at finish(), or not at all. Or to
// memory (image/png_write.hpp): a whole image is encoded before its file is opened, so that a
// process killed while encoding leaves no temporary file behind.
#pragma once

#include "io/atomic_file.hpp"

#include <cstdint>
#include <string>

namespace fr {

class PngStream {
 public:
  // Writes the header of a width_px x height_px RGBA8 image. Throws std::runtime_error.
  PngStream(OutputFile& out, int width_px, int height_px);
  // The same, appending the PNG's bytes to `memory`.
  PngStream(std::string& memory, int width_px, int height_px);
  ~PngStream();
  PngStream(const PngStream&) = delete;
  PngStream& operator=(const PngStream&) = delete;

  // The next `rows` rows, top to bottom, 4 bytes a pixel. Throws std::runtime_error.
  void write_rows(const uint8_t* rgba8, int rows);
  // After the last row: the end of the stream, then the file committed (if it is one). Throws.
  void finish();

  struct State;  // libpng's structures and the first error (png_stream.cpp)

 private:
  PngStream(OutputFile* out, std::string* memory, int width_px, int height_px);

  State* state_;
  OutputFile* out_;  // nullptr: the bytes go to memory
  int width_px_, height_px_, rows_written_ = 0;
};

}  // namespace fr
