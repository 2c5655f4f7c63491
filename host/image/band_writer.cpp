#include "image/band_writer.hpp"

#include <stdexcept>

namespace fr {

BandWriter::BandWriter(const std::filesystem::path& file, int width_px, int height_px)
    : exr_(is_exr_file_name(file)) {
  std::string error;
  out_ = OutputFile::open(file, &error);
  if (!out_) throw std::runtime_error(error);
  if (exr_)
    exr_stream_.emplace(*out_, width_px, height_px);
  else
    png_.emplace(*out_, width_px, height_px);
}

void BandWriter::write_rows(const FrameImage& band) {
  if (exr_)
    exr_stream_->write_rows(band);
  else
    png_->write_rows(band.rgba8.data(), band.height_px);
}

void BandWriter::finish() {
  if (exr_)
    exr_stream_->finish();
  else
    png_->finish();
}

}  // namespace fr
