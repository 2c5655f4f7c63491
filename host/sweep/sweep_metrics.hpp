// sweep_metrics.hpp — how far one rendered frame is from the sweep's reference: image error,
// geometric error in pixel footprints, and the counts that make a picture silently wrong.
// Pure functions of the two images, so they are tested on hand-made ones.
#pragma once

#include "render/renderer.hpp"

#include <cstdint>
#include <vector>

namespace fr {

// What a configuration is compared with (sweep_reference.hpp makes it): the converged picture
// and, from centred rays, the converged geometry.
struct ReferenceImage {
  int width_px = 0, height_px = 0;
  std::vector<uint8_t> rgba8;  // many samples per pixel
  std::vector<float> depth;    // centre ray of each pixel; +inf for a miss
  std::vector<float> normal;   // 3 per pixel, unit; 0 for a miss
};

struct ErrorMetrics {
  double mean_abs_error = 0;         // mean |difference| over pixels and RGB, in 8-bit units
  double psnr_db = 0;                // 20 log10(255 / RMS difference); +inf when identical
  double fraction_over_8 = 0;        // pixels with a channel off by more than 8/255
  double depth_median_px = 0;        // |depth - reference| / footprint where both hit: median
  double depth_p95_px = 0;           // ... and 95th percentile (nearest rank)
  double silhouette_mismatch = 0;    // fraction of pixels that hit in one and miss in the other
  double normal_p95_deg = 0;         // angle between normals where both hit, 95th percentile
  double overstep_rate = 0;          // fraction of reference hits rendered behind the surface
  double out_of_steps_fraction = 0;  // primary rays that ran out of steps
  size_t non_finite = 0;             // NaN or infinite values in colour, normals or depth (hits)
};

// A reference as a frame (what compare_to_reference takes), every ray's status a hit or a miss.
FrameImage reference_as_frame(const ReferenceImage& reference);

// How far behind the reference surface (in footprints) a hit must be to count as an overstep:
// the reference's own threshold is far below a footprint, so a quarter is already past it.
constexpr double kOverstepFootprints = 0.25;

// Compares `image` (read back with Readback::Everything) with `reference` of the same size; the
// footprint of a pixel is reference depth x pixel_angle_rad.
ErrorMetrics compare_to_reference(const FrameImage& image, const ReferenceImage& reference,
                                  double pixel_angle_rad);

// Indices of the points on the Pareto front of (time, error), both to be small: each is faster
// than every point with less or equal error. In increasing time.
std::vector<size_t> pareto_front(const std::vector<double>& time, const std::vector<double>& error);

}  // namespace fr
