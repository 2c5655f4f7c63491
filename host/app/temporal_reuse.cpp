#include "app/temporal_reuse.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>

namespace fr {
namespace {

// The rays of a CameraRays in float, for per-pixel use: the ray through column x and row y is
// normalise(base + x * dx + y * dy) (camera_ray_dir's arithmetic, regrouped); and projection's
// inverse pixel pitches.
struct FloatCamera {
  glm::vec3 base, dx, dy, right, up, forward;
  float centre_x, centre_y, px_per_unit_x, px_per_unit_y;
  explicit FloatCamera(const CameraRays& r) {
    const double last_x = r.width_px - 1, last_y = r.height_px - 1;
    base = glm::vec3(r.first_pixel_dir + r.pixel_step_x * last_x + r.pixel_step_y * last_y);
    dx = glm::vec3(-r.pixel_step_x);
    dy = glm::vec3(-r.pixel_step_y);
    right = glm::vec3(r.right);
    up = glm::vec3(r.up);
    forward = glm::vec3(r.forward);
    centre_x = static_cast<float>(0.5 * last_x);
    centre_y = static_cast<float>(0.5 * last_y);
    const double sx = glm::length(r.pixel_step_x), sy = glm::length(r.pixel_step_y);
    px_per_unit_x = sx > 0 ? static_cast<float>(1 / sx) : 0.0f;
    px_per_unit_y = sy > 0 ? static_cast<float>(1 / sy) : 0.0f;
  }
};

// Four floats at a time (GCC's and Clang's vector extensions: SSE on x86-64, NEON on ARM).
using f4 = float __attribute__((vector_size(16)));
using i4 = int32_t __attribute__((vector_size(16)));
f4 load4(const float* p) {
  f4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
void store4(float* p, f4 v) {
  std::memcpy(p, &v, sizeof v);
}
f4 splat(float v) {
  return f4{v, v, v, v};
}

uint32_t load_rgba(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

}  // namespace

int LatticePhase::width_px(int full_width_px) const {
  return full_width_px > x0 ? (full_width_px - x0 + stride_x - 1) / stride_x : 0;
}

int LatticePhase::height_px(int full_height_px) const {
  return full_height_px > y0 ? (full_height_px - y0 + stride_y - 1) / stride_y : 0;
}

LatticePhase lattice_phase(int stride_x, int stride_y, uint64_t frame) {
  LatticePhase p;
  p.stride_x = std::max(1, stride_x);
  p.stride_y = std::max(1, stride_y);
  const uint64_t k = frame % static_cast<uint64_t>(p.stride_x * p.stride_y);
  // Row by row of the cycle, each row's columns shifted by its index: consecutive frames trace
  // lattices that are apart in x and in y (for 2x2: (0,0), (1,1)... as a checkerboard's halves).
  const uint64_t row = k / static_cast<uint64_t>(p.stride_x);
  p.y0 = static_cast<int>(row % static_cast<uint64_t>(p.stride_y));
  p.x0 = static_cast<int>((k + row) % static_cast<uint64_t>(p.stride_x));
  return p;
}

void TemporalReuse::Samples::resize(size_t n) {
  // Padded by a vector, which the projection reads past the end.
  x.resize(n + kLanes);
  y.resize(n + kLanes);
  z.resize(n + kLanes);
  rgba8.resize(n);
  kind.resize(n + kLanes);
  age.resize(n + kLanes);
}

struct TemporalReuse::Frame {
  const LatticePhase& phase;
  const uint8_t* rgba8;  // the lattice's
  const float* depth;
  int max_age;
  bool carry;  // kept_ holds samples of old_rays_
  FloatCamera cam;
  glm::vec3 shift;  // the old eye seen from the new one
  int width_px, height_px, lattice_w, lattice_h;
  // Per image column (or row): the lattice columns (rows) on either side of it, `first` and
  // `first + 1` (the first or last two beyond the lattice's ends; both 0 in a lattice one column
  // wide); the weight of the second for interpolating, clamped to [0, 1]; and whether the pixel
  // lies between the two.
  struct Span {
    int first = 0, second = 0;
    float weight = 0;
    bool bracketed = false;
  };
  std::vector<Span> columns, rows;
  // The unit ray through pixel (x, y).
  glm::vec3 ray(int x, int y) const {
    const glm::vec3 r = cam.base + cam.dx * static_cast<float>(x) + cam.dy * static_cast<float>(y);
    return r * (1.0f / std::sqrt(glm::dot(r, r)));
  }
  size_t lattice_at(int i, int j) const { return static_cast<size_t>(j) * lattice_w + i; }
};

const uint8_t* TemporalReuse::compose(const CameraRays& rays, const LatticePhase& phase,
                                      const uint8_t* lattice_rgba8, const float* lattice_depth) {
  const int w = rays.width_px, h = rays.height_px;
  const size_t n = static_cast<size_t>(w) * h;
  if (w != width_px_ || h != height_px_) {
    has_history_ = false;
    width_px_ = w;
    height_px_ = h;
  }
  kept_.resize(n);
  next_.resize(n);
  // Padded by a vector: the projection runs to a whole vector past the end.
  landed_x_.resize(n + kLanes);
  landed_y_.resize(n + kLanes);
  landed_key2_.resize(n + kLanes);
  const bool whole = phase.stride_x == 1 && phase.stride_y == 1;
  Frame f{phase,
          lattice_rgba8,
          lattice_depth,
          std::min(254, std::max(settings_.max_age_frames, 2 * phase.stride_x * phase.stride_y)),
          has_history_ && !whole,
          FloatCamera(rays),
          glm::vec3(old_rays_.eye - rays.eye),  // in double: the scene may be far from the origin
          w,
          h,
          phase.width_px(w),
          phase.height_px(h),
          {},
          {}};
  slots_.resize(slot_stride(w) * h);
  const auto spans = [](int size_px, int origin, int stride, int lattice_size) {
    std::vector<Frame::Span> spans(static_cast<size_t>(size_px));
    for (int x = 0; x < size_px; ++x) {
      Frame::Span& s = spans[static_cast<size_t>(x)];
      const float u = static_cast<float>(x - origin) / static_cast<float>(stride);
      if (lattice_size < 2) continue;  // one column: the same sample on both sides
      s.first = std::clamp(static_cast<int>(std::floor(u)), 0, lattice_size - 2);
      s.second = s.first + 1;
      s.weight = std::clamp(u - static_cast<float>(s.first), 0.0f, 1.0f);
      s.bracketed = u >= 0 && u <= static_cast<float>(lattice_size - 1);
    }
    return spans;
  };
  f.columns = spans(w, phase.x0, phase.stride_x, f.lattice_w);
  f.rows = spans(h, phase.y0, phase.stride_y, f.lattice_h);
  // Each pass in two halves, one per thread: the projection reads and writes only its own
  // samples; the gather reads anything the projection wrote.
  const auto on_two_threads = [](int size, const auto& pass) {
    std::thread second([&] { pass(size / 2, size); });
    pass(0, size / 2);
    second.join();
  };
  if (f.carry) {
    on_two_threads(h, [&](int begin, int /*end*/) {
      // The samples split at a whole vector (the arrays are padded past the end).
      const size_t split = n / 2 / kLanes * kLanes;
      project_samples(f, begin == 0 ? 0 : split, begin == 0 ? split : n);
    });
    on_two_threads(h, [&](int begin, int end) { scatter_rows(f, begin, end); });
  }
  ReuseCounts halves[2];
  on_two_threads(h, [&](int begin, int end) { gather_rows(f, begin, end, halves[begin > 0]); });
  counts_ = ReuseCounts{};
  for (const ReuseCounts& c : halves) {
    counts_.fresh += c.fresh;
    counts_.reused += c.reused;
    counts_.rejected += c.rejected;
    counts_.filled += c.filled;
  }
  std::swap(kept_, next_);
  has_history_ = true;
  old_rays_ = rays;
  return reinterpret_cast<const uint8_t*>(kept_.rgba8.data());
}

// Where every kept sample in [begin, end) lands in the new image, and its distance from the new
// eye, squared (its vector is moved there when the gather copies it: not written back here,
// which would cost as much memory traffic as the rest). A vector of samples at a time, up to a
// whole vector past `end` (the arrays are padded).
void TemporalReuse::project_samples(const Frame& f, size_t begin, size_t end) {
  const FloatCamera& cam = f.cam;
  const glm::vec3 rx = cam.right * cam.px_per_unit_x, uy = cam.up * cam.px_per_unit_y;
  const f4 nan = splat(std::numeric_limits<float>::quiet_NaN()), inf = splat(INFINITY);
  for (size_t i = begin; i < end; i += kLanes) {
    i4 surface, usable;
    for (int lane = 0; lane < kLanes; ++lane) {
      const uint8_t kind = kept_.kind[i + lane];
      surface[lane] = kind == kSurface ? -1 : 0;
      usable[lane] = kind != kNone && kept_.age[i + lane] < f.max_age ? -1 : 0;
    }
    // The sky's directions do not move with the eye.
    const f4 move = surface ? splat(1.0f) : splat(0.0f);
    const f4 x = load4(&kept_.x[i]) + move * f.shift.x;
    const f4 y = load4(&kept_.y[i]) + move * f.shift.y;
    const f4 z = load4(&kept_.z[i]) + move * f.shift.z;
    const f4 along = x * cam.forward.x + y * cam.forward.y + z * cam.forward.z;
    const f4 px = cam.centre_x + (x * rx.x + y * rx.y + z * rx.z) / along;
    const f4 py = cam.centre_y - (x * uy.x + y * uy.y + z * uy.z) / along;
    store4(&landed_x_[i], usable && along > 0 ? px : nan);
    store4(&landed_y_[i], py);
    store4(&landed_key2_[i], surface ? x * x + y * y + z * z : inf);
  }
}

// Every kept sample, offered to each pixel of rows [row_begin, row_end) whose centre its point
// lands within 0.87 px of (at most the four around it): the pixel's slot keeps the best one offered
// (sample_key: the nearest surface, then the nearest the centre, then the lowest index, so the
// result does not depend on the order). One thread per half of the rows: each reads every
// sample's landing position, and writes only its own rows' slots.
void TemporalReuse::scatter_rows(const Frame& f, int row_begin, int row_end) {
  const int w = f.width_px;
  const size_t stride = slot_stride(w);
  // Column -1 and column w of each row are padding (slot index 0 is column -1 of row 0): a point
  // beside the image offers itself there unchecked.
  uint64_t* __restrict slot = slots_.data();
  std::fill(slot + row_begin * stride, slot + row_end * stride, kNoSample);
  const float* __restrict landed_x = landed_x_.data();
  const float* __restrict landed_y = landed_y_.data();
  const float* __restrict key2 = landed_key2_.data();
  const float top = static_cast<float>(row_begin - 1), bottom = static_cast<float>(row_end);
  const float right = static_cast<float>(w);
  const size_t n = static_cast<size_t>(w) * f.height_px;
  const auto offer = [](uint64_t& s, uint64_t near, float d2, size_t i) {
    // (d2 > 0.75: too far from this pixel's centre; the slot keeps what it has.)
    const uint64_t key = d2 <= 0.75f ? sample_key(near, d2, i) : kNoSample;
    s = key < s ? key : s;
  };
  for (size_t i = 0; i < n; ++i) {
    const float x = landed_x[i], y = landed_y[i];
    // (False for NaN: a sample not usable, or behind the new eye.)
    if (!(y > top && y < bottom && x > -1.0f && x < right)) continue;
    // The pixels around the point: columns x0 and x0 + 1, rows y0 and y0 + 1 ((int)(v + 1) - 1
    // is floor(v) for v > -1).
    const int x0 = static_cast<int>(x + 1.0f) - 1, y0 = static_cast<int>(y + 1.0f) - 1;
    const float dx0 = x - static_cast<float>(x0), dx1 = dx0 - 1.0f;
    const float dy0 = y - static_cast<float>(y0), dy1 = dy0 - 1.0f;
    const uint64_t near = sample_nearness(key2[i]);
    // Pixel (x0, y0)'s slot, negative for row -1 (then only the row below is offered).
    const ptrdiff_t at = static_cast<ptrdiff_t>(y0) * static_cast<ptrdiff_t>(stride) + x0 + 1;
    if (y0 >= row_begin) {
      offer(slot[at], near, dx0 * dx0 + dy0 * dy0, i);
      offer(slot[at + 1], near, dx1 * dx1 + dy0 * dy0, i);
    }
    if (y0 + 1 < row_end) {
      const size_t below = static_cast<size_t>(at + static_cast<ptrdiff_t>(stride));
      offer(slot[below], near, dx0 * dx0 + dy1 * dy1, i);
      offer(slot[below + 1], near, dx1 * dx1 + dy1 * dy1, i);
    }
  }
}

void TemporalReuse::gather_rows(const Frame& f, int row_begin, int row_end,
                                ReuseCounts& counts_out) {
  ReuseCounts counts;  // here, not in counts_out: the threads' counts share a cache line
  const LatticePhase& phase = f.phase;
  const int w = f.width_px;
  const float margin = 1 + settings_.occlusion_tolerance, margin2 = margin * margin;
  const bool carry = f.carry;
  // Through local pointers: a byte store may alias anything, and would make the compiler reload
  // every vector's address after it.
  float* __restrict next_x = next_.x.data();
  float* __restrict next_y = next_.y.data();
  float* __restrict next_z = next_.z.data();
  uint32_t* __restrict next_rgba8 = next_.rgba8.data();
  uint8_t* __restrict next_kind = next_.kind.data();
  uint8_t* __restrict next_age = next_.age.data();
  const uint64_t* __restrict slot = slots_.data();
  const size_t stride = slot_stride(w);
  const auto set = [&](size_t at, const glm::vec3& v, uint32_t rgba8, uint8_t kind, int age) {
    next_x[at] = v.x;
    next_y[at] = v.y;
    next_z[at] = v.z;
    next_rgba8[at] = rgba8;
    next_kind[at] = kind;
    next_age[at] = static_cast<uint8_t>(age);
  };
  for (int y = row_begin; y < row_end; ++y) {
    const Frame::Span& row = f.rows[static_cast<size_t>(y)];
    const bool lattice_row = y >= phase.y0 && (y - phase.y0) % phase.stride_y == 0;
    int next_lattice_x = lattice_row ? phase.x0 : w;  // the row's next fresh pixel
    for (int x = 0; x < w; ++x) {
      const size_t at = static_cast<size_t>(y) * w + x;
      if (x == next_lattice_x) {
        next_lattice_x += phase.stride_x;
        const size_t from =
            f.lattice_at((x - phase.x0) / phase.stride_x, (y - phase.y0) / phase.stride_y);
        const float t = f.depth[from];
        const bool surface = std::isfinite(t);
        const glm::vec3 d = f.ray(x, y);
        set(at, surface ? d * t : d, load_rgba(f.rgba8 + 4 * from), surface ? kSurface : kSky, 0);
        ++counts.fresh;
        continue;
      }
      // The lattice around this pixel: its four samples.
      const Frame::Span& col = f.columns[static_cast<size_t>(x)];
      const size_t corner[4] = {
          f.lattice_at(col.first, row.first), f.lattice_at(col.second, row.first),
          f.lattice_at(col.first, row.second), f.lattice_at(col.second, row.second)};
      const float fu = col.weight, fv = row.weight;
      const float weight[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
      if (carry) {
        const uint64_t best = slot[static_cast<size_t>(y) * stride + x + 1];
        if (best != kNoSample) {
          const size_t k = sample_index(best);
          // Every fresh sample around it is nearer: something now stands in front of it. (Not
          // beyond the lattice's last row or column, where the samples are on one side and a
          // surface sloping away is deeper than all of them.)
          float farthest = 0;
          for (size_t c : corner) farthest = std::max(farthest, f.depth[c]);  // +inf: the sky
          if (col.bracketed && row.bracketed && landed_key2_[k] > farthest * farthest * margin2) {
            ++counts.rejected;
          } else {
            const uint8_t kind = kept_.kind[k];
            const glm::vec3 v(kept_.x[k], kept_.y[k], kept_.z[k]);
            set(at, kind == kSurface ? v + f.shift : v, kept_.rgba8[k], kind, kept_.age[k] + 1);
            ++counts.reused;
            continue;
          }
        }
      }
      // Nothing carried: the fresh lattice, bilinearly, kept one more frame at most.
      uint32_t c = 0;
      for (int ch = 0; ch < 4; ++ch) {
        float sum = 0;
        for (int k = 0; k < 4; ++k) sum += weight[k] * f.rgba8[4 * corner[k] + ch];
        c |= static_cast<uint32_t>(sum + 0.5f) << (8 * ch);
      }
      float guess = 0, guess_weight = 0;
      for (int k = 0; k < 4; ++k) {
        const float t = f.depth[corner[k]];
        if (std::isfinite(t)) {
          guess += weight[k] * t;
          guess_weight += weight[k];
        }
      }
      const glm::vec3 d = f.ray(x, y);
      const bool surface = guess_weight > 0;
      set(at, surface ? d * (guess / guess_weight) : d, c, surface ? kSurface : kSky,
          std::max(0, f.max_age - 1));
      ++counts.filled;
    }
  }
  counts_out = counts;
}

}  // namespace fr
