// band_writer.hpp — an image file written a band of rows at a time, top to bottom: a PNG
// (png_stream.hpp), or an OpenEXR file with every pass when it is named *.exr (exr_write.hpp).
// The encoding half of a poster (poster.hpp drives the renderer); the file appears, atomically,
// only at finish().
#pragma once

#include "image/exr_write.hpp"
#include "image/png_stream.hpp"
#include "io/atomic_file.hpp"
#include "render/renderer.hpp"

#include <filesystem>
#include <memory>
#include <optional>

namespace fr {

class BandWriter {
 public:
  // Opens `file` for a width_px x height_px image; throws std::runtime_error saying why not.
  BandWriter(const std::filesystem::path& file, int width_px, int height_px);
  // The passes a band must be read back with for `file` (an EXR's every pass).
  static Readback passes_for(const std::filesystem::path& file) {
    return is_exr_file_name(file) ? Readback::Everything : Readback::DisplayAndSteps;
  }
  // The same for this writer's file.
  Readback passes() const { return exr_ ? Readback::Everything : Readback::DisplayAndSteps; }
  // The next band's rows, as rendered (a window of the whole image).
  void write_rows(const FrameImage& band);
  // Ends the file and puts it in place. Without it, nothing is left at the file's name.
  void finish();

 private:
  std::unique_ptr<OutputFile> out_;
  bool exr_ = false;
  std::optional<PngStream> png_;
  std::optional<ExrStream> exr_stream_;
};

}  // namespace fr
