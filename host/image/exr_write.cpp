#include "image/exr_write.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>

#include <Iex.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <optional>

namespace fr {
namespace {

// OpenEXR's output stream over an OutputFile: it seeks back to write the scanline offsets.
class OutputFileStream : public Imf::OStream {
 public:
  OutputFileStream(OutputFile& out, const std::string& name)
      : Imf::OStream(name.c_str()), out_(out) {}
  void write(const char c[], int n) override {
    if (!out_.write(std::string_view(c, static_cast<size_t>(n)), &error_)) throw Iex::IoExc(error_);
  }
  uint64_t tellp() override { return out_.position(); }
  void seekp(uint64_t pos) override {
    if (!out_.seek(pos, &error_)) throw Iex::IoExc(error_);
  }
  // Imf::OutputFile writes its scanline offsets in its destructor, which swallows exceptions:
  // the first failure is kept here for the caller to check afterwards.
  const std::string& error() const { return error_; }

 private:
  OutputFile& out_;
  std::string error_;
};

struct Channel {
  const char* name;
  int component;  // of the FrameImage field
};

const Channel kRgba[] = {{"R", 0}, {"G", 1}, {"B", 2}, {"A", 3}};
const Channel kNormal[] = {{"N.x", 0}, {"N.y", 1}, {"N.z", 2}};
const Channel kAlbedo[] = {{"albedo.R", 0}, {"albedo.G", 1}, {"albedo.B", 2}};

}  // namespace

struct ExrStream::State {
  OutputFile& out;
  OutputFileStream stream;
  std::optional<Imf::OutputFile> exr;
  int width = 0, height = 0, rows_written = 0;
  State(OutputFile& o, const std::string& name) : out(o), stream(o, name) {}
};

std::string exr_unavailable_reason() {
  return {};
}

ExrStream::ExrStream(OutputFile& out, int width_px, int height_px) {
  if (!out.seekable())
    throw std::runtime_error(
        "an EXR file cannot go to a pipe or device (OpenEXR seeks back to index its scanlines)");
  state_ = std::make_unique<State>(out, "EXR");
  state_->width = width_px;
  state_->height = height_px;
  Imf::Header header(width_px, height_px);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.lineOrder() = Imf::INCREASING_Y;
  Imf::addComments(header, "rendered by fractalis; Z is the distance along each pixel's ray");
  for (const Channel& c : kRgba) header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
  header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
  for (const Channel& c : kNormal) header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
  for (const Channel& c : kAlbedo) header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
  header.channels().insert("steps", Imf::Channel(Imf::FLOAT));
  header.channels().insert("mask", Imf::Channel(Imf::FLOAT));
  try {
    state_->exr.emplace(state_->stream, header);
  } catch (const std::exception& e) {
    throw std::runtime_error(state_->stream.error().empty() ? e.what() : state_->stream.error());
  }
}

ExrStream::~ExrStream() = default;

void ExrStream::write_rows(const FrameImage& band) {
  State& s = *state_;
  const size_t w = static_cast<size_t>(s.width), rows = static_cast<size_t>(band.height_px);
  const size_t n = w * rows;
  if (band.width_px != s.width || rows == 0 || s.rows_written + band.height_px > s.height ||
      band.linear_rgba.size() != n * 4 || band.depth.size() != n || band.normal.size() != n * 3 ||
      band.albedo.size() != n * 3 || band.steps.size() != n || band.ray_status.size() != n)
    throw std::runtime_error("an EXR band lacks its passes or does not fit the image");
  std::vector<float> mask(n);
  for (size_t i = 0; i < n; ++i)
    mask[i] = static_cast<RayStatus>(band.ray_status[i]) == RayStatus::Hit ? 1.0f : 0.0f;
  // OpenEXR finds pixel (x, y) of the whole image at base + x * xStride + y * yStride, so each
  // slice's base is the band's first row moved up by the rows above it (computed as integers:
  // the address itself lies outside the band and is never read).
  const int y0 = s.rows_written;
  Imf::FrameBuffer frame;
  auto add = [&](const char* name, const float* first, size_t floats_per_pixel) {
    const size_t x_stride = sizeof(float) * floats_per_pixel, y_stride = x_stride * w;
    const uintptr_t base =
        reinterpret_cast<uintptr_t>(first) - static_cast<uintptr_t>(y0) * y_stride;
    frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(base), x_stride, y_stride));
  };
  for (const Channel& c : kRgba) add(c.name, band.linear_rgba.data() + c.component, 4);
  add("Z", band.depth.data(), 1);
  for (const Channel& c : kNormal) add(c.name, band.normal.data() + c.component, 3);
  for (const Channel& c : kAlbedo) add(c.name, band.albedo.data() + c.component, 3);
  add("steps", band.steps.data(), 1);
  add("mask", mask.data(), 1);
  try {
    s.exr->setFrameBuffer(frame);
    s.exr->writePixels(band.height_px);
  } catch (const std::exception& e) {
    throw std::runtime_error(s.stream.error().empty() ? e.what() : s.stream.error());
  }
  s.rows_written += band.height_px;
}

void ExrStream::finish() {
  State& s = *state_;
  if (s.rows_written != s.height) throw std::runtime_error("an EXR file ended before its last row");
  s.exr.reset();  // writes the scanline offsets
  if (!s.stream.error().empty()) throw std::runtime_error(s.stream.error());
  std::string error;
  if (!s.out.commit(&error)) throw std::runtime_error(error);
}

bool write_exr_atomic(const std::filesystem::path& file, const FrameImage& image,
                      std::string* error) {
  auto out = OutputFile::open(file, error);
  if (!out) return false;
  try {
    ExrStream exr(*out, image.width_px, image.height_px);
    exr.write_rows(image);
    exr.finish();
    return true;
  } catch (const std::exception& e) {
    const std::string what = e.what();
    *error = what.rfind("cannot write " + file.string(), 0) == 0
                 ? what
                 : "cannot write " + file.string() + ": " + what;
    return false;
  }
}

}  // namespace fr
