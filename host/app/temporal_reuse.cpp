#include "app/temporal_reuse.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <thread>

namespace fr {
namespace {

constexpr float kSkyKey = FLT_MAX;

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

const uint8_t* TemporalReuse::compose(const CameraRays& rays, const LatticePhase& phase,
                                      const uint8_t* lattice_rgba8, const float* lattice_depth) {
  const size_t n = static_cast<size_t>(rays.width_px) * rays.height_px;
  if (rays.width_px != width_px_ || rays.height_px != height_px_) {
    has_history_ = false;
    width_px_ = rays.width_px;
    height_px_ = rays.height_px;
  }
  next_.resize(n);
  kept_.resize(n);
  shown_.resize(n * 4);
  const bool whole = phase.stride_x == 1 && phase.stride_y == 1;
  const int max_age =
      std::min(254, std::max(settings_.max_age_frames, 2 * phase.stride_x * phase.stride_y));
  const Frame frame{rays,     phase, lattice_rgba8, lattice_depth, max_age, has_history_ && !whole,
                    old_rays_};
  // Rows in two halves, one per thread: each pixel only reads the frames before and the lattice.
  ReuseCounts halves[2];
  const int split = rays.height_px / 2;
  std::thread second([&] { compose_rows(frame, split, rays.height_px, halves[1]); });
  compose_rows(frame, 0, split, halves[0]);
  second.join();
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
  return shown_.data();
}

void TemporalReuse::compose_rows(const Frame& f, int row_begin, int row_end,
                                 ReuseCounts& counts_out) {
  ReuseCounts counts;  // here, not in counts_out: the threads' counts share a cache line
  const CameraRays& rays = f.rays;
  const LatticePhase& phase = f.phase;
  const FloatCamera cam(rays), old_cam(f.old_rays);
  const int w = rays.width_px, h = rays.height_px;
  const int lw = phase.width_px(w), lh = phase.height_px(h);
  // The old eye seen from the new one, in double (the scene may be far from the origin).
  const glm::vec3 shift(f.old_rays.eye - rays.eye);
  const glm::vec3 rx = cam.right * cam.px_per_unit_x, uy = cam.up * cam.px_per_unit_y;
  const glm::vec3 old_rx = old_cam.right * old_cam.px_per_unit_x;
  const glm::vec3 old_uy = old_cam.up * old_cam.px_per_unit_y;
  const float margin = 1 + settings_.occlusion_tolerance;
  // Where a vector from the new eye lands in the new image (false: behind the eye).
  const auto project = [&](const glm::vec3& v, float& x, float& y) {
    const float along = glm::dot(v, cam.forward);
    if (!(along > 0)) return false;
    const float inv = 1.0f / along;
    x = cam.centre_x + glm::dot(v, rx) * inv;
    y = cam.centre_y - glm::dot(v, uy) * inv;
    return true;
  };
  const auto lattice_at = [&](int i, int j) { return static_cast<size_t>(j) * lw + i; };
  const float inv_stride_x = 1.0f / phase.stride_x, inv_stride_y = 1.0f / phase.stride_y;
  for (int y = row_begin; y < row_end; ++y) {
    const glm::vec3 row_dir = cam.base + cam.dy * static_cast<float>(y);
    const bool lattice_row = y >= phase.y0 && (y - phase.y0) % phase.stride_y == 0;
    // The lattice rows at or above and below this one, and the weight of the lower.
    const float v = std::clamp(static_cast<float>(y - phase.y0) * inv_stride_y, 0.0f,
                               static_cast<float>(lh - 1));
    const int j0 = static_cast<int>(v), j1 = std::min(j0 + 1, lh - 1);
    const float fv = v - j0;
    // Between two lattice rows (not beyond the first or last): the occlusion test applies.
    const bool bracketed_y = y >= phase.y0 && j1 > j0;
    int next_lattice_x = lattice_row ? phase.x0 : w;  // the row's next fresh pixel
    for (int x = 0; x < w; ++x) {
      Sample& s = next_[static_cast<size_t>(y) * w + x];
      uint8_t* shown = &shown_[4 * (static_cast<size_t>(y) * w + x)];
      const glm::vec3 ray = row_dir + cam.dx * static_cast<float>(x);
      const glm::vec3 d = ray * (1.0f / std::sqrt(glm::dot(ray, ray)));
      if (x == next_lattice_x) {
        next_lattice_x += phase.stride_x;
        const size_t from =
            lattice_at((x - phase.x0) / phase.stride_x, (y - phase.y0) / phase.stride_y);
        const float t = f.depth[from];
        const bool surface = std::isfinite(t);
        const glm::vec3 p = surface ? d * t : d;
        s = Sample{
            {p.x, p.y, p.z}, load_rgba(f.rgba8 + 4 * from), surface ? Kind::Surface : Kind::Sky, 0};
        std::memcpy(shown, &s.rgba8, 4);
        ++counts.fresh;
        continue;
      }
      // The lattice around this pixel: its four samples, their depths' bilinear guess and the
      // farthest of them.
      const float u = std::clamp(static_cast<float>(x - phase.x0) * inv_stride_x, 0.0f,
                                 static_cast<float>(lw - 1));
      const int i0 = static_cast<int>(u), i1 = std::min(i0 + 1, lw - 1);
      const float fu = u - i0;
      const bool bracketed = bracketed_y && x >= phase.x0 && i1 > i0;
      const size_t corner[4] = {lattice_at(i0, j0), lattice_at(i1, j0), lattice_at(i0, j1),
                                lattice_at(i1, j1)};
      const float weight[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
      float farthest = 0, guess = 0, guess_weight = 0;
      for (int k = 0; k < 4; ++k) {
        const float t = f.depth[corner[k]];
        farthest = std::max(farthest, std::isfinite(t) ? t : kSkyKey);
        if (std::isfinite(t)) {
          guess += weight[k] * t;
          guess_weight += weight[k];
        }
      }
      bool found = false;
      if (f.carry) {
        // Where this pixel's ray meets the scene, guessed from the lattice (the sky: its
        // direction), seen from the old camera; the old samples around there whose own points
        // land within a pixel of this one are candidates, the nearest of them wins.
        const glm::vec3 p = guess_weight > 0 ? d * (guess / guess_weight) : d;
        const glm::vec3 q = guess_weight > 0 ? p - shift : p;  // from the old eye
        const float along = glm::dot(q, old_cam.forward);
        if (along > 1e-12f) {  // in front of the old eye, and 1 / along finite
          const float inv = 1.0f / along;
          // Clamped before the conversion: a point just in front of the old eye lands anywhere
          // (and a float beyond int's range would not convert).
          const auto old_pixel = [](float at, int size) {
            return static_cast<int>(std::floor(std::clamp(at + 0.5f, -2.0f, size + 2.0f)));
          };
          const int ox = old_pixel(old_cam.centre_x + glm::dot(q, old_rx) * inv, w);
          const int oy = old_pixel(old_cam.centre_y - glm::dot(q, old_uy) * inv, h);
          float best_key = INFINITY, best_d2 = 0;
          const Sample* best = nullptr;
          // The old sample at the guessed position when its point lands within 0.87 px of this
          // pixel (most often: then no search); else the nearest of those around it that do.
          const auto consider = [&](int sx, int sy) {
            const Sample& o = kept_[static_cast<size_t>(sy) * w + sx];
            if (o.kind == Kind::None || o.age >= f.max_age) return;
            glm::vec3 ov(o.vec[0], o.vec[1], o.vec[2]);
            if (o.kind == Kind::Surface) ov += shift;
            float px, py;
            if (!project(ov, px, py)) return;
            const float d2 = (px - x) * (px - x) + (py - y) * (py - y);
            if (!(d2 <= 0.75f)) return;  // (NaN too)
            // Nearest first (its distance from the new eye); between samples of one surface,
            // the one nearest the pixel.
            const float key = o.kind == Kind::Surface ? glm::length(ov) : kSkyKey;
            if (!best || key < best_key / margin || (key <= best_key * margin && d2 < best_d2)) {
              best = &o;
              best_key = key;
              best_d2 = d2;
            }
          };
          if (ox >= 0 && oy >= 0 && ox < w && oy < h) consider(ox, oy);
          if (!best)
            for (int sy = std::max(0, oy - 1); sy <= std::min(h - 1, oy + 1); ++sy)
              for (int sx = std::max(0, ox - 1); sx <= std::min(w - 1, ox + 1); ++sx)
                consider(sx, sy);
          if (best) {
            // Every fresh sample around it is nearer: something now stands in front of it.
            // (Not beyond the lattice's last row or column, where the samples are on one side
            // and a surface sloping away is deeper than all of them.)
            if (bracketed && best_key > farthest * margin) {
              ++counts.rejected;
            } else {
              glm::vec3 ov(best->vec[0], best->vec[1], best->vec[2]);
              if (best->kind == Kind::Surface) ov += shift;
              s = Sample{
                  {ov.x, ov.y, ov.z}, best->rgba8, best->kind, static_cast<uint8_t>(best->age + 1)};
              found = true;
              ++counts.reused;
            }
          }
        }
      }
      if (found) {
        std::memcpy(shown, &s.rgba8, 4);
        continue;
      }
      // Nothing carried: the fresh lattice, bilinearly, kept one more frame at most.
      uint32_t c = 0;
      for (int ch = 0; ch < 4; ++ch) {
        float sum = 0;
        for (int k = 0; k < 4; ++k) sum += weight[k] * f.rgba8[4 * corner[k] + ch];
        c |= static_cast<uint32_t>(sum + 0.5f) << (8 * ch);
      }
      const bool surface = guess_weight > 0;
      const float t = surface ? guess / guess_weight : kSkyKey;
      const glm::vec3 p = surface ? d * t : d;
      s = Sample{{p.x, p.y, p.z},
                 c,
                 surface ? Kind::Surface : Kind::Sky,
                 static_cast<uint8_t>(std::max(0, f.max_age - 1))};
      std::memcpy(shown, &s.rgba8, 4);
      ++counts.filled;
    }
  }
  counts_out = counts;
}

}  // namespace fr
