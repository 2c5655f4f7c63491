// temporal_reuse.hpp — full resolution while flying: what earlier frames traced, carried into the
// new camera (issue 37).
//
// Each frame traces one lattice of the window's pixels (every stride_x-th column of every
// stride_y-th row, from a phase that rotates so that every pixel is traced again within
// stride_x * stride_y frames: RenderSettings::window). Every other pixel gathers what the
// frames before traced: each kept sample is the point its ray hit (the vector from the eye to it)
// or, for the sky, its direction. A pixel guesses where in the old image its ray met the scene
// from the fresh lattice's samples around it (where each of their points was seen in the old
// camera, interpolated), and takes the kept sample whose own point lands within 0.87 px of it
// (the old pixel at the guess if it does, else the nearest of its neighbours that do), carrying
// that exact point on, so positions do not drift from frame to frame. A carried sample is rejected
// where the fresh lattice samples around it are all nearer than it by more than a tolerance
// (something came in front of it), and when it is older than `max_age_frames`. A pixel left without
// one (a disocclusion, the image's new edge) takes the fresh lattice's bilinear value. The scene
// must not have changed (the caller resets the history when anything but the camera did); colours
// are display values (rgba8), so exposure and tone mapping must be the same.
//
// Two passes, each on two threads: every kept sample is projected into the new image (one
// vectorised pass over the samples, by field), then every pixel looks at the old image where the
// lattice's own old positions, interpolated, say its ray came from (tests/temporal_reuse_bench
// times it; docs/performance.md, "Temporal reuse").
#pragma once

#include "render/camera.hpp"

#include <cstddef>
#include <cstdint>
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
  static constexpr int kLanes = 4;  // floats in one vector of the projection and the search
  void project_samples(const Frame& frame, size_t begin, size_t end);
  void project_lattice_rows(const Frame& frame, int row_begin, int row_end);
  void gather_rows(const Frame& frame, int row_begin, int row_end, ReuseCounts& counts);

  TemporalReuseSettings settings_;
  Samples kept_, next_;
  // Per kept sample, where it lands in the new image (NaN: nowhere usable), and its distance
  // from the new eye, squared (+inf: the sky).
  std::vector<float> landed_x_, landed_y_, landed_key2_;
  // Per fresh lattice sample, where its point was in the old image (NaN: behind the old eye), and
  // whether it is a surface.
  std::vector<float> lattice_old_x_, lattice_old_y_;
  std::vector<uint8_t> lattice_surface_;
  bool has_history_ = false;
  int width_px_ = 0, height_px_ = 0;
  CameraRays old_rays_;  // the camera of kept_ (its vectors start at its eye)
  ReuseCounts counts_;
};

}  // namespace fr
