// The video encoder of a build without FFmpeg (FRACTALIS_VIDEO=OFF: the Windows build, whose
// FFmpeg would need x264 and libvpx cross-built too): every video is refused, saying why, and
// animations go to folders of PNG frames instead.
#include "video/video_encoder.hpp"

namespace fr {

struct VideoEncoder::State {};

std::string video_unavailable_reason() {
  return "this build of fractalis has no video encoder (it was built without FFmpeg)";
}

std::unique_ptr<VideoEncoder> VideoEncoder::open(const std::filesystem::path& file, int, int, int,
                                                 std::string* error) {
  *error = "cannot write " + file.string() + ": " + video_unavailable_reason();
  return nullptr;
}

VideoEncoder::~VideoEncoder() = default;

bool VideoEncoder::add_frame(const std::vector<uint8_t>&, std::string* error) {
  *error = video_unavailable_reason();
  return false;
}

bool VideoEncoder::finish(std::string* error) {
  *error = video_unavailable_reason();
  return false;
}

}  // namespace fr
