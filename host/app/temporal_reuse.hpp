// temporal_reuse.hpp — full resolution while flying: what earlier frames traced, carried into the
// new camera (issue 37).
//
// Each frame traces one lattice of the window's pixels (every stride_x-th column of every
// stride_y-th row, from a phase that rotates so that every pixel is traced again within
// stride_x * stride_y frames: RenderSettings::window). Every other pixel takes what the frames
// before traced: each kept sample is the point its ray hit (the vector from the eye to it) or, for
// the sky, its direction. Every kept sample is projected into the new camera and offered to the
// pixels whose centres its point lands within 0.87 px of (at most four); a pixel keeps, of those
// offered, the nearest surface's (within a few percent) that lands nearest its centre. The exact
// point is carried on, so positions do not drift from frame to frame. A carried sample is rejected
// where the fresh lattice samples around it are all nearer than it by more than a tolerance
// (something came in front of it), and when it is older than `max_age_frames`. A pixel left without
// one (a disocclusion, the image's new edge) takes the fresh lattice's bilinear value. The scene
// must not have changed (the caller resets the history when anything but the camera did); colours
// are display values (rgba8), so exposure and tone mapping must be the same.
//
// Three passes, each on two threads: every kept sample is projected into the new image (one
// vectorised pass over the samples, by field), offered to the pixels around where it lands (each
// thread to those of its half of the rows), and every pixel takes the best
// (tests/temporal_reuse_bench times it; docs/performance.md, "Temporal reuse").
#pragma once

#include "render/camera.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace fr {

// Which pixels of a width x height image a frame traces: (x0 + i * stride_x, y0 + j * stride_y).
struct LatticePhase {
  int stride_x = 1;
  int stride_y = 1;
  int x0 = 0;
  int y0 = 0;
  int width_px(int full_width_px) const;  // the lattice's columns in an image that wide
  int height_px(int full_height_px) const;
};

// Phase `frame` of the strides' cycle: each of the stride_x * stride_y offsets once per cycle,
// neighbours of the cycle apart in both directions.
LatticePhase lattice_phase(int stride_x, int stride_y, uint64_t frame);

// What one frame's pixels came from.
struct ReuseCounts {
  size_t fresh = 0;     // traced this frame (the lattice)
  size_t reused = 0;    // carried from earlier frames
  size_t rejected = 0;  // a carried sample here failed the occlusion test
  size_t filled = 0;    // nothing carried: the fresh lattice's, bilinearly (rejected ones too)
};

struct TemporalReuseSettings {
  float occlusion_tolerance = 0.03f;  // relative depth margin of the occlusion test
  // A carried sample older than this is not used (at least twice the lattice's cycle).
  int max_age_frames = 24;
};

class TemporalReuse {
 public:
  explicit TemporalReuse(TemporalReuseSettings settings = {}) : settings_(settings) {}

  // Forgets every kept sample: the next frame uses only what it traces.
  void reset() { has_history_ = false; }
  bool has_history() const { return has_history_; }

  // The frame `rays` sees (the whole window's camera): the kept samples carried to it, and the
  // lattice `phase` traced fresh (`lattice_rgba8` and `lattice_depth`, the distance along each
  // ray from the eye, +inf for the sky, of phase.width_px x phase.height_px pixels). Returns the
  // window-sized rgba8 image, valid until the next call; its samples are kept for the next frame.
  // With strides 1 the lattice is the whole frame (a full trace: nothing is carried).
  const uint8_t* compose(const CameraRays& rays, const LatticePhase& phase,
                         const uint8_t* lattice_rgba8, const float* lattice_depth);

  const ReuseCounts& counts() const { return counts_; }

 private:
  // Kind of a kept sample.
  static constexpr uint8_t kNone = 0, kSurface = 1, kSky = 2;
  // The kept samples of one frame, a pixel each, by field (so the projection pass runs on whole
  // vectors of them): the vector from the eye to the hit point (a surface) or the unit direction
  // (the sky); the display colour (rgba8: these are the shown image); kind; frames since traced.
  struct Samples {
    std::vector<float> x, y, z;
    std::vector<uint32_t> rgba8;
    std::vector<uint8_t> kind, age;
    void resize(size_t n);
  };
  // One compose call's inputs and the arrays its passes share.
  struct Frame;
  static constexpr int kLanes = 4;  // floats in one vector of the projection
  void project_samples(const Frame& frame, size_t begin, size_t end);
  void scatter_rows(const Frame& frame, int row_begin, int row_end);
  void gather_rows(const Frame& frame, int row_begin, int row_end, ReuseCounts& counts);

  TemporalReuseSettings settings_;
  Samples kept_, next_;
  // Per kept sample, where it lands in the new image (NaN: nowhere usable), and its distance
  // from the new eye, squared (+inf: the sky).
  std::vector<float> landed_x_, landed_y_, landed_key2_;
  // Per pixel of the new image, the best kept sample offered to it (sample_key), or kNoSample;
  // each row with a column of padding on either side.
  std::vector<uint64_t> slots_;
  static size_t slot_stride(int width_px) { return static_cast<size_t>(width_px) + 2; }
  static constexpr uint64_t kNoSample = ~uint64_t{0};
  // The order in which a pixel prefers the samples offered to it, as one integer (smaller is
  // better): the distance from the new eye (its square's float bits, to 4 bits of mantissa:
  // samples within about 3% are of one surface), then how far from the pixel's centre it landed
  // (d2, in pixels squared, at most 0.75: its float bits, which order as the values do, to 12
  // bits of mantissa), then its index (which the key carries).
  static uint64_t float_bits(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
  }
  static uint64_t sample_nearness(float key2) {
    return float_bits(key2) >> 19 << 52;  // 12 bits: key2 is not negative
  }
  static uint64_t sample_key(uint64_t nearness, float d2, size_t index) {
    return nearness | float_bits(d2) >> 11 << 32 | static_cast<uint64_t>(index);  // 20 bits
  }
  static size_t sample_index(uint64_t key) { return static_cast<size_t>(key & 0xffffffffu); }
  bool has_history_ = false;
  int width_px_ = 0, height_px_ = 0;
  CameraRays old_rays_;  // the camera of kept_ (its vectors start at its eye)
  ReuseCounts counts_;
};

}  // namespace fr
