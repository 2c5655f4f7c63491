// exr_read.hpp — an OpenEXR file read back with the OpenEXR library, every channel as float.
#pragma once

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fr::test {

struct ExrImage {
  int width = 0, height = 0;
  std::set<std::string> channel_names;
  std::map<std::string, std::vector<float>> channels;
};

inline ExrImage read_exr(const std::filesystem::path& file) {
  Imf::InputFile in(file.c_str());
  const auto box = in.header().dataWindow();
  ExrImage image;
  image.width = box.max.x - box.min.x + 1;
  image.height = box.max.y - box.min.y + 1;
  Imf::FrameBuffer frame;
  for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c) {
    image.channel_names.insert(c.name());
    auto& data = image.channels[c.name()];
    data.resize(size_t(image.width) * image.height);
    frame.insert(c.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(data.data()),
                                      sizeof(float), sizeof(float) * image.width));
  }
  in.setFrameBuffer(frame);
  in.readPixels(box.min.y, box.max.y);
  return image;
}

}  // namespace fr::test
