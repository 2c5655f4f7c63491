#include "video/video_encoder.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace fr {
namespace {

constexpr std::array<VideoFormat, 3> kFormats = {{
    {".mp4", "mp4", "libx264", "H.264"},
    {".mkv", "matroska", "libx264", "H.264"},
    {".webm", "webm", "libvpx-vp9", "VP9"},
}};

}  // namespace

const VideoFormat* video_format_for(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const auto& f : kFormats)
    if (ext == f.extension) return &f;
  return nullptr;
}

std::string video_extension_list() {
  std::string list;
  for (const auto& f : kFormats) {
    if (!list.empty()) list += ", ";
    list.append("'").append(f.extension).append("'");
  }
  return list;
}

}  // namespace fr
