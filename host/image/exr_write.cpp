#include "image/exr_write.hpp"

#include "io/atomic_file.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>

#include <Iex.h>

#include <algorithm>
#include <cctype>

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

}  // namespace

bool is_exr_file_name(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".exr";
}

bool write_exr_atomic(const std::filesystem::path& file, const FrameImage& image,
                      std::string* error) {
  const size_t w = static_cast<size_t>(image.width_px), h = static_cast<size_t>(image.height_px);
  const size_t n = w * h;
  if (n == 0 || image.linear_rgba.size() != n * 4 || image.depth.size() != n ||
      image.normal.size() != n * 3 || image.albedo.size() != n * 3 || image.steps.size() != n ||
      image.ray_status.size() != n) {
    *error = "cannot write " + file.string() + ": the frame lacks its passes";
    return false;
  }
  std::vector<float> mask(n);
  for (size_t i = 0; i < n; ++i)
    mask[i] = static_cast<RayStatus>(image.ray_status[i]) == RayStatus::Hit ? 1.0f : 0.0f;

  auto out = OutputFile::open(file, error);
  if (!out) return false;
  if (!out->seekable()) {
    *error = "cannot write " + file.string() +
             ": OpenEXR seeks back to index its scanlines, and a pipe or device cannot";
    return false;
  }
  OutputFileStream stream(*out, file.string());
  try {
    Imf::Header header(image.width_px, image.height_px);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::addComments(header, "rendered by fractalis; Z is the distance along each pixel's ray");
    Imf::FrameBuffer frame;
    auto add = [&](const char* name, const float* base, size_t floats_per_pixel) {
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      frame.insert(
          name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(base)),
                           sizeof(float) * floats_per_pixel, sizeof(float) * floats_per_pixel * w));
    };
    const char* rgba[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) add(rgba[c], image.linear_rgba.data() + c, 4);
    add("Z", image.depth.data(), 1);
    const char* normal[] = {"N.x", "N.y", "N.z"};
    for (int c = 0; c < 3; ++c) add(normal[c], image.normal.data() + c, 3);
    const char* albedo[] = {"albedo.R", "albedo.G", "albedo.B"};
    for (int c = 0; c < 3; ++c) add(albedo[c], image.albedo.data() + c, 3);
    add("steps", image.steps.data(), 1);
    add("mask", mask.data(), 1);
    Imf::OutputFile exr(stream, header);
    exr.setFrameBuffer(frame);
    exr.writePixels(image.height_px);
  } catch (const std::exception& e) {
    const std::string what = e.what();
    *error =
        what.rfind("cannot write", 0) == 0 ? what : "cannot write " + file.string() + ": " + what;
    return false;
  }
  if (!stream.error().empty()) {
    *error = stream.error();
    return false;
  }
  return out->commit(error);
}

}  // namespace fr
