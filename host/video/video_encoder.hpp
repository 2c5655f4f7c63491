// video_encoder.hpp — frames in, an encoded video file out, through the FFmpeg libraries
// (libavcodec, libavformat, libswscale).
//
// The container follows the file's extension: .mp4 and .mkv hold H.264 (libx264, CRF 15), .webm
// holds VP9 (libvpx-vp9, CRF 31, constant quality). Frames are 8-bit sRGB RGBA, converted to
// yuv420p with the BT.709 matrix in limited range and tagged so, which is what players expect
// of HD video; yuv420p halves the chroma both ways, so width and height must be even.
//
// Frame i is shown from i / fps to (i + 1) / fps: N frames make a video N / fps seconds long.
// The file is written like every output (io/atomic_file.hpp): a temporary file renamed into
// place by finish(), removed when encoding fails or the encoder is destroyed unfinished. MP4
// patches its index after the data and so cannot go to a pipe; Matroska and WebM can.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fr {

struct VideoFormat {
  const char* extension;  // ".mp4"
  const char* muxer;      // FFmpeg's container name
  const char* encoder;    // FFmpeg's encoder name
  const char* codec;      // what a user calls it: "H.264"
};

// The format for an output file name, or nullptr when its extension is not a video's.
const VideoFormat* video_format_for(const std::filesystem::path& file);
// "'.mp4', '.mkv', '.webm'", for messages.
std::string video_extension_list();
// Empty where this build writes videos; otherwise why it cannot (video_encoder_missing.cpp).
std::string video_unavailable_reason();

class VideoEncoder {
 public:
  // Nullptr with *error when the file cannot be written or the encoder cannot be opened.
  static std::unique_ptr<VideoEncoder> open(const std::filesystem::path& file, int width_px,
                                            int height_px, int fps, std::string* error);
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Encodes the next frame: width_px * height_px * 4 bytes, rows top to bottom.
  bool add_frame(const std::vector<uint8_t>& rgba8, std::string* error);
  // Drains the encoder, writes the container's trailer and puts the file in place.
  bool finish(std::string* error);

  struct State;

 private:
  VideoEncoder() = default;
  std::unique_ptr<State> state_;
};

}  // namespace fr
