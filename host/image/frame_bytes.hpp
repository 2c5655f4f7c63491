// frame_bytes.hpp — a FrameImage (render/renderer.hpp) as bytes and back, for sending a rendered
// frame or poster band from one process of an MPI job to the one that writes it. Both ends are
// the same fractalis build: the layout is this build's, native byte order, not a file format.
#pragma once

#include "render/renderer.hpp"

#include <cstdint>
#include <vector>

namespace fr {

// Appends `image`, every field, to `out`.
void append_frame_bytes(const FrameImage& image, std::vector<uint8_t>& out);
// Reads a frame from `bytes` at *at (advanced past it) into `image`; throws std::runtime_error
// when the bytes are cut short or sizes disagree.
void read_frame_bytes(const std::vector<uint8_t>& bytes, size_t* at, FrameImage& image);

}  // namespace fr
