#include "video/video_encoder.hpp"

#include "io/atomic_file.hpp"

#include <spdlog/spdlog.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <array>
#include <cstdarg>
#include <cstdio>
#include <mutex>

namespace fr {
namespace {

std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// FFmpeg's messages go to the log (warnings and errors only: x264's statistics are noise here).
void log_from_ffmpeg(void* avcl, int level, const char* format, va_list args) {
  if (level > AV_LOG_WARNING) return;
  static int print_prefix = 1;
  char line[1024];
  va_list copy;
  va_copy(copy, args);
  av_log_format_line2(avcl, level, format, copy, line, sizeof line, &print_prefix);
  va_end(copy);
  std::string text(line);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  if (text.empty()) return;
  if (level <= AV_LOG_ERROR)
    spdlog::error("ffmpeg: {}", text);
  else
    spdlog::warn("ffmpeg: {}", text);
}

}  // namespace

std::string video_unavailable_reason() {
  return {};
}

struct VideoEncoder::State {
  std::filesystem::path file;
  std::unique_ptr<OutputFile> output;
  uint64_t size_bytes = 0;  // end of the file written so far, for SEEK_END
  std::string io_error;
  AVFormatContext* format = nullptr;
  AVIOContext* io = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* scale = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  int width = 0, height = 0;
  int64_t next_pts = 0;
  bool header_written = false;

  ~State() {
    av_packet_free(&packet);
    av_frame_free(&frame);
    sws_freeContext(scale);
    avcodec_free_context(&codec);
    if (io) {
      av_freep(&io->buffer);
      avio_context_free(&io);
    }
    avformat_free_context(format);
  }

  bool fail(const std::string& what, int code, std::string* error) {
    *error = "cannot write " + file.string() + ": " + what;
    if (!io_error.empty())
      *error += ": " + io_error;
    else if (code < 0)
      *error += ": " + av_error(code);
    return false;
  }

  static int write_packet(void* opaque, uint8_t* buf, int size) {
    auto* s = static_cast<State*>(opaque);
    if (!s->output->write(std::string_view(reinterpret_cast<const char*>(buf), size), &s->io_error))
      return AVERROR(EIO);
    s->size_bytes = std::max(s->size_bytes, s->output->position());
    return size;
  }

  static int64_t seek(void* opaque, int64_t offset, int whence) {
    auto* s = static_cast<State*>(opaque);
    int64_t to = offset;
    switch (whence & ~AVSEEK_FORCE) {
      case AVSEEK_SIZE:
        return static_cast<int64_t>(s->size_bytes);
      case SEEK_SET:
        break;
      case SEEK_CUR:
        to += static_cast<int64_t>(s->output->position());
        break;
      case SEEK_END:
        to += static_cast<int64_t>(s->size_bytes);
        break;
      default:
        return AVERROR(EINVAL);
    }
    if (to < 0 || !s->output->seek(static_cast<uint64_t>(to), &s->io_error)) return AVERROR(EIO);
    return to;
  }

  // Sends `f` (nullptr: end of stream) and writes every packet the encoder has ready.
  bool encode(AVFrame* f, std::string* error) {
    int rc = avcodec_send_frame(codec, f);
    if (rc < 0) return fail("encoding failed", rc, error);
    for (;;) {
      rc = avcodec_receive_packet(codec, packet);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return true;
      if (rc < 0) return fail("encoding failed", rc, error);
      if (packet->duration == 0) packet->duration = 1;  // one frame, in the codec's time base
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format, packet);  // takes the packet's data
      if (rc < 0) return fail("writing a frame failed", rc, error);
    }
  }
};

std::unique_ptr<VideoEncoder> VideoEncoder::open(const std::filesystem::path& file, int width_px,
                                                 int height_px, int fps, std::string* error) {
  static std::once_flag log_once;
  std::call_once(log_once, [] {
    av_log_set_level(AV_LOG_WARNING);
    av_log_set_callback(log_from_ffmpeg);
  });
  const VideoFormat* vf = video_format_for(file);
  if (!vf) {
    *error = "cannot write " + file.string() + ": not a video file name (" +
             video_extension_list() + ")";
    return nullptr;
  }
  if (width_px % 2 != 0 || height_px % 2 != 0) {
    *error = "cannot write " + file.string() + ": yuv420p video needs an even width and height";
    return nullptr;
  }
  std::unique_ptr<VideoEncoder> encoder(new VideoEncoder());
  encoder->state_ = std::make_unique<State>();
  State& s = *encoder->state_;
  s.file = file;
  s.width = width_px;
  s.height = height_px;

  const AVCodec* codec = avcodec_find_encoder_by_name(vf->encoder);
  if (!codec) {
    *error = std::string("cannot write ") + file.string() + ": this FFmpeg has no " + vf->encoder +
             " encoder for " + vf->codec;
    return nullptr;
  }
  int rc = avformat_alloc_output_context2(&s.format, nullptr, vf->muxer, nullptr);
  if (rc < 0 || !s.format) {
    s.fail(std::string("no ") + vf->muxer + " muxer", rc, error);
    return nullptr;
  }
  s.codec = avcodec_alloc_context3(codec);
  s.packet = av_packet_alloc();
  s.frame = av_frame_alloc();
  if (!s.codec || !s.packet || !s.frame) {
    s.fail("out of memory", AVERROR(ENOMEM), error);
    return nullptr;
  }
  s.codec->width = width_px;
  s.codec->height = height_px;
  s.codec->time_base = AVRational{1, fps};
  s.codec->framerate = AVRational{fps, 1};
  s.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  s.codec->gop_size = std::max(1, 2 * fps);  // a key frame every 2 s: seeking stays quick
  s.codec->color_range = AVCOL_RANGE_MPEG;
  s.codec->colorspace = AVCOL_SPC_BT709;
  s.codec->color_primaries = AVCOL_PRI_BT709;
  s.codec->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB-encoded
  s.codec->thread_count = 0;                    // the encoder's choice: every core
  if (s.format->oformat->flags & AVFMT_GLOBALHEADER) s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  if (codec->id == AV_CODEC_ID_H264) {
    // A video must be a function of its frames alone: the same from one process as from the
    // ranks of an MPI job, whose frames reach the encoder at other times. Here (x264 164 through
    // libavcodec 59) macroblock-tree rate control and frame threads each made different videos
    // of the same frames from run to run; without the one and with threads inside each frame
    // instead, the same bytes every time (tests/mpi_test.cpp), on every core still. Without the
    // tree, CRF 18 quantised more coarsely (a 49-frame 640x360 Mandelbulb clip: PSNR 35.6 dB
    // instead of 38.0); CRF 15 gives it back (38.3 dB, a 6% larger file). Visually lossless for
    // most content.
    av_dict_set(&options, "crf", "15", 0);
    av_dict_set(&options, "preset", "medium", 0);
    av_dict_set(&options, "x264-params", "mbtree=0:sliced-threads=1", 0);
  } else {
    av_dict_set(&options, "crf", "31", 0);
    av_dict_set(&options, "b", "0", 0);  // with crf: constant quality, no bitrate cap
    av_dict_set(&options, "deadline", "good", 0);
    av_dict_set(&options, "cpu-used", "4", 0);
    av_dict_set(&options, "row-mt", "1", 0);
  }
  rc = avcodec_open2(s.codec, codec, &options);
  av_dict_free(&options);
  if (rc < 0) {
    s.fail(std::string("cannot open the ") + vf->encoder + " encoder", rc, error);
    return nullptr;
  }
  s.stream = avformat_new_stream(s.format, nullptr);
  if (!s.stream) {
    s.fail("out of memory", AVERROR(ENOMEM), error);
    return nullptr;
  }
  s.stream->time_base = s.codec->time_base;
  s.stream->avg_frame_rate = s.codec->framerate;
  rc = avcodec_parameters_from_context(s.stream->codecpar, s.codec);
  if (rc < 0) {
    s.fail("cannot set the stream's parameters", rc, error);
    return nullptr;
  }

  s.frame->format = AV_PIX_FMT_YUV420P;
  s.frame->width = width_px;
  s.frame->height = height_px;
  s.frame->color_range = AVCOL_RANGE_MPEG;
  s.frame->colorspace = AVCOL_SPC_BT709;
  rc = av_frame_get_buffer(s.frame, 0);
  if (rc < 0) {
    s.fail("out of memory", rc, error);
    return nullptr;
  }
  s.scale = sws_getContext(width_px, height_px, AV_PIX_FMT_RGBA, width_px, height_px,
                           AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                           nullptr, nullptr, nullptr);
  if (!s.scale) {
    s.fail("cannot convert RGBA to yuv420p", 0, error);
    return nullptr;
  }
  // Full-range RGB in, limited-range BT.709 out.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(s.scale, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

  s.output = OutputFile::open(file, error);
  if (!s.output) return nullptr;
  constexpr int kBufferBytes = 1 << 16;
  auto* buffer = static_cast<unsigned char*>(av_malloc(kBufferBytes));
  s.io = avio_alloc_context(buffer, kBufferBytes, 1, &s, nullptr, &State::write_packet,
                            s.output->seekable() ? &State::seek : nullptr);
  if (!buffer || !s.io) {
    if (!s.io) av_free(buffer);
    s.fail("out of memory", AVERROR(ENOMEM), error);
    return nullptr;
  }
  s.io->seekable = s.output->seekable() ? AVIO_SEEKABLE_NORMAL : 0;
  s.format->pb = s.io;
  s.format->flags |= AVFMT_FLAG_CUSTOM_IO;
  rc = avformat_write_header(s.format, nullptr);
  if (rc < 0) {
    s.fail(s.output->seekable() ? "cannot start the container"
                                : "cannot start the container (MP4 cannot go to a pipe: use .mkv)",
           rc, error);
    return nullptr;
  }
  s.header_written = true;
  return encoder;
}

VideoEncoder::~VideoEncoder() = default;

bool VideoEncoder::add_frame(const std::vector<uint8_t>& rgba8, std::string* error) {
  State& s = *state_;
  if (rgba8.size() != static_cast<size_t>(s.width) * s.height * 4) {
    *error = "cannot write " + s.file.string() + ": a frame of the wrong size";
    return false;
  }
  const int rc = av_frame_make_writable(s.frame);
  if (rc < 0) return s.fail("out of memory", rc, error);
  const uint8_t* source[1] = {rgba8.data()};
  const int stride[1] = {s.width * 4};
  sws_scale(s.scale, source, stride, 0, s.height, s.frame->data, s.frame->linesize);
  s.frame->pts = s.next_pts++;
  return s.encode(s.frame, error);
}

bool VideoEncoder::finish(std::string* error) {
  State& s = *state_;
  if (!s.encode(nullptr, error)) return false;
  int rc = av_write_trailer(s.format);
  if (rc < 0) return s.fail("cannot finish the container", rc, error);
  avio_flush(s.io);
  if (s.io->error < 0) return s.fail("write failed", s.io->error, error);
  return s.output->commit(error);
}

}  // namespace fr
