// exr_write.hpp — a rendered frame as an OpenEXR file with its passes, for compositing.
//
// Channels (32-bit float, ZIP-compressed scanlines, written with the OpenEXR library):
//   R, G, B, A          the linear HDR image (the mean of every sample), not tonemapped; A = 1
//   Z                   distance from the eye along the pixel's ray to the surface (scene units;
//                       not the planar depth); +inf where the ray missed
//   N.x, N.y, N.z       unit surface normal in world space; 0 where the ray missed
//   albedo.R/.G/.B      the surface's albedo (linear); 0 where the ray missed
//   steps               DE evaluations of the primary ray
//   mask                1 where the primary ray hit the surface, else 0 (missed, ran out of steps,
//                       or started inside the solid)
// The passes other than RGBA are those of the last sample's primary rays (renderer.hpp).
// The file is written like every output (io/atomic_file.hpp): whole or not at all.
#pragma once

#include "io/atomic_file.hpp"
#include "render/renderer.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace fr {

// True when `file`'s name ends in .exr (any case).
inline bool is_exr_file_name(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  return ext.size() == 4 && ext[0] == '.' && (ext[1] | 0x20) == 'e' && (ext[2] | 0x20) == 'x' &&
         (ext[3] | 0x20) == 'r';
}
// Empty where this build writes EXR files; otherwise why it cannot (exr_write_missing.cpp).
std::string exr_unavailable_reason();

// An EXR written a band of rows at a time (posters: image/poster.hpp), top to bottom, into an
// OutputFile, which must be seekable (OpenEXR goes back to index its scanlines).
class ExrStream {
 public:
  // Writes the header of a width_px x height_px image. Throws std::runtime_error.
  ExrStream(OutputFile& out, int width_px, int height_px);
  ~ExrStream();
  ExrStream(const ExrStream&) = delete;
  ExrStream& operator=(const ExrStream&) = delete;

  // The next band: a frame read back with Readback::Everything, as wide as the image.
  void write_rows(const FrameImage& band);
  // After the last row: the scanline index, then the file committed. Throws.
  void finish();

  struct State;

 private:
  std::unique_ptr<State> state_;
};

// Writes `image` (read back with Readback::Everything) whole. On failure returns false with
// *error naming the file and why, leaving any existing file untouched.
bool write_exr_atomic(const std::filesystem::path& file, const FrameImage& image,
                      std::string* error);

}  // namespace fr
