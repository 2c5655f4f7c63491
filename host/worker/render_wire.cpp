#include "worker/render_wire.hpp"

namespace fr {

void write_render_settings(WireWriter& w, const RenderSettings& s) {
  w.raw(&s, sizeof s);
}

RenderSettings read_render_settings(WireReader& r) {
  RenderSettings s;
  r.raw(&s, sizeof s);
  return s;
}

FramePassPointers frame_passes_at(uint8_t* base, size_t n, Readback what, size_t* total_bytes) {
  size_t at = 0;
  // Each pass starts on a cache line of its own.
  const auto take = [&](size_t bytes) -> uint8_t* {
    uint8_t* p = base ? base + at : nullptr;
    at += (bytes + 63) / 64 * 64;
    return p;
  };
  FramePassPointers p;
  p.rgba8 = take(n * 4);
  if (what != Readback::Display) {
    p.steps = reinterpret_cast<float*>(take(n * 4));
    p.ray_status = take(n);
  }
  if (what == Readback::Everything) {
    p.linear_rgba = reinterpret_cast<float*>(take(n * 16));
    p.depth = reinterpret_cast<float*>(take(n * 4));
    p.occlusion = reinterpret_cast<float*>(take(n * 4));
    p.shadow = reinterpret_cast<float*>(take(n * 4));
    p.normal = reinterpret_cast<float*>(take(n * 12));
    p.albedo = reinterpret_cast<float*>(take(n * 12));
  }
  *total_bytes = at;
  return p;
}

}  // namespace fr
