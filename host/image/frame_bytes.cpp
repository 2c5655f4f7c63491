#include "image/frame_bytes.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace fr {
namespace {

void append_raw(std::vector<uint8_t>& out, const void* data, size_t n) {
  const size_t at = out.size();
  out.resize(at + n);
  if (n > 0) std::memcpy(out.data() + at, data, n);
}

template <typename T>
void append_vector(std::vector<uint8_t>& out, const std::vector<T>& v) {
  const uint64_t count = v.size();
  append_raw(out, &count, sizeof count);
  append_raw(out, v.data(), v.size() * sizeof(T));
}

void read_raw(const std::vector<uint8_t>& in, size_t* at, void* data, size_t n) {
  if (in.size() < *at || in.size() - *at < n)
    throw std::runtime_error("a frame's bytes end early (" + std::to_string(in.size()) +
                             " bytes, " + std::to_string(*at + n) + " needed)");
  if (n > 0) std::memcpy(data, in.data() + *at, n);
  *at += n;
}

template <typename T>
void read_vector(const std::vector<uint8_t>& in, size_t* at, std::vector<T>& v) {
  uint64_t count = 0;
  read_raw(in, at, &count, sizeof count);
  if (count > (in.size() - *at) / sizeof(T))
    throw std::runtime_error("a frame's bytes end early (a pass of " + std::to_string(count) +
                             " values)");
  v.resize(count);
  read_raw(in, at, v.data(), count * sizeof(T));
}

}  // namespace

void append_frame_bytes(const FrameImage& image, std::vector<uint8_t>& out) {
  const int32_t header[4] = {image.width_px, image.height_px, image.lanes,
                             static_cast<int32_t>(image.precision)};
  append_raw(out, header, sizeof header);
  append_vector(out, image.rgba8);
  append_vector(out, image.linear_rgba);
  append_vector(out, image.depth);
  append_vector(out, image.steps);
  append_vector(out, image.occlusion);
  append_vector(out, image.shadow);
  append_vector(out, image.normal);
  append_vector(out, image.albedo);
  append_vector(out, image.ray_status);
}

void read_frame_bytes(const std::vector<uint8_t>& bytes, size_t* at, FrameImage& image) {
  int32_t header[4] = {};
  read_raw(bytes, at, header, sizeof header);
  image.width_px = header[0];
  image.height_px = header[1];
  image.lanes = header[2];
  image.precision = static_cast<Precision>(header[3]);
  read_vector(bytes, at, image.rgba8);
  read_vector(bytes, at, image.linear_rgba);
  read_vector(bytes, at, image.depth);
  read_vector(bytes, at, image.steps);
  read_vector(bytes, at, image.occlusion);
  read_vector(bytes, at, image.shadow);
  read_vector(bytes, at, image.normal);
  read_vector(bytes, at, image.albedo);
  read_vector(bytes, at, image.ray_status);
  const size_t pixels = static_cast<size_t>(std::max(image.width_px, 0)) *
                        static_cast<size_t>(std::max(image.height_px, 0));
  if (image.rgba8.size() != 4 * pixels)
    throw std::runtime_error("a frame's bytes hold " + std::to_string(image.rgba8.size()) +
                             " colour bytes for " + std::to_string(image.width_px) + "x" +
                             std::to_string(image.height_px) + " pixels");
}

}  // namespace fr
