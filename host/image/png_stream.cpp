#include "image/png_stream.hpp"

#include <png.h>

#include <csetjmp>
#include <stdexcept>

namespace fr {

struct PngStream::State {
  png_structp png = nullptr;
  png_infop info = nullptr;
  OutputFile* out = nullptr;      // the file, or
  std::string* memory = nullptr;  // the bytes in memory
  std::string error;              // the first failure, from libpng or from the file
};

namespace {

void on_write(png_structp png, png_bytep data, png_size_t length) {
  auto* s = static_cast<PngStream::State*>(png_get_io_ptr(png));
  if (s->memory) {
    s->memory->append(reinterpret_cast<const char*>(data), length);
    return;
  }
  std::string error;
  if (!s->out->write(std::string_view(reinterpret_cast<const char*>(data), length), &error)) {
    if (s->error.empty()) s->error = error;
    png_error(png, "write failed");
  }
}
void on_flush(png_structp) {}
void on_error(png_structp png, png_const_charp message) {
  auto* s = static_cast<PngStream::State*>(png_get_error_ptr(png));
  if (s->error.empty()) s->error = std::string("PNG encoding failed: ") + message;
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp: each call into it runs in a plain C-style function that sets
// its own jump point and holds no C++ object with a destructor.
bool guarded_header(PngStream::State* s, png_uint_32 w, png_uint_32 h) {
  if (setjmp(png_jmpbuf(s->png))) return false;
  png_set_IHDR(s->png, s->info, w, h, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Level 3 and the Sub filter: a poster's gigabyte of rows compresses several times faster
  // than at the defaults, for files a little larger.
  png_set_compression_level(s->png, 3);
  png_set_filter(s->png, 0, PNG_FILTER_SUB);
  png_write_info(s->png, s->info);
  return true;
}
bool guarded_rows(PngStream::State* s, const uint8_t* rgba8, int rows, int width_px) {
  if (setjmp(png_jmpbuf(s->png))) return false;
  for (int r = 0; r < rows; ++r)
    png_write_row(s->png, const_cast<png_bytep>(rgba8 + static_cast<size_t>(r) * width_px * 4));
  return true;
}
bool guarded_end(PngStream::State* s) {
  if (setjmp(png_jmpbuf(s->png))) return false;
  png_write_end(s->png, s->info);
  return true;
}

}  // namespace

PngStream::PngStream(OutputFile& out, int width_px, int height_px)
    : PngStream(&out, nullptr, width_px, height_px) {}

PngStream::PngStream(std::string& memory, int width_px, int height_px)
    : PngStream(nullptr, &memory, width_px, height_px) {}

PngStream::PngStream(OutputFile* out, std::string* memory, int width_px, int height_px)
    : state_(new State), out_(out), width_px_(width_px), height_px_(height_px) {
  state_->out = out;
  state_->memory = memory;
  state_->png = png_create_write_struct(PNG_LIBPNG_VER_STRING, state_, on_error, on_warning);
  if (state_->png) state_->info = png_create_info_struct(state_->png);
  if (!state_->png || !state_->info) {
    png_destroy_write_struct(&state_->png, &state_->info);
    delete state_;
    throw std::runtime_error("PNG encoding failed: out of memory");
  }
  png_set_write_fn(state_->png, state_, on_write, on_flush);
  if (!guarded_header(state_, static_cast<png_uint_32>(width_px),
                      static_cast<png_uint_32>(height_px))) {
    const std::string error = state_->error;
    png_destroy_write_struct(&state_->png, &state_->info);
    delete state_;
    throw std::runtime_error(error);
  }
}

PngStream::~PngStream() {
  png_destroy_write_struct(&state_->png, &state_->info);
  delete state_;
}

void PngStream::write_rows(const uint8_t* rgba8, int rows) {
  if (rows_written_ + rows > height_px_)
    throw std::logic_error("PngStream: more rows than the image");
  if (!guarded_rows(state_, rgba8, rows, width_px_)) throw std::runtime_error(state_->error);
  rows_written_ += rows;
}

void PngStream::finish() {
  if (rows_written_ != height_px_) throw std::logic_error("PngStream: rows missing");
  if (!guarded_end(state_)) throw std::runtime_error(state_->error);
  std::string error;
  if (out_ && !out_->commit(&error)) throw std::runtime_error(error);
}

}  // namespace fr
