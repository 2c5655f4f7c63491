// poster.hpp — an image of any size up to 65535 x 65535, rendered a band of rows at a time and
// streamed to a PNG (png_stream.hpp) or, for a file named *.exr, to an OpenEXR file with its
// passes (exr_write.hpp), so memory stays that of one band however large the image.
//
// Each band is a window of the whole image (RenderSettings::window): the kernel computes its rays
// from the whole image's pixel grid, the same rays bit for bit, so bands join without seams and
// the file is the same as a render of the whole. Every band gets all
// of settings.samples. Auto precision is decided once for the whole view, so that no band
// switches precision on its own.
#pragma once

#include "render/renderer.hpp"
#include "worker/render_worker.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>

namespace fr {

// Pixels per band by default: 8 M (about 0.4 GB of device buffers and 0.2 GB on the host).
constexpr uint64_t kPosterBandPixels = 8u << 20;

// An EXR band reads every pass back (81 bytes a pixel on the host, not 9): half the pixels.
constexpr uint64_t kExrPosterBandPixels = kPosterBandPixels / 2;
// The band size for `file`: kExrPosterBandPixels for *.exr, else kPosterBandPixels.
uint64_t poster_band_pixels(const std::filesystem::path& file);

// Rows per band for a width_px x height_px poster: whole rows within band_pixels, at least one.
int poster_band_rows(int width_px, int height_px, uint64_t band_pixels = kPosterBandPixels);

// The settings every band of a poster renders with: the whole image's, no window, precision
// decided once for the whole view (never Auto). Throws std::runtime_error for an empty size.
RenderSettings poster_settings(RenderWorker& worker, const SceneInfo& info, const SceneState& state,
                               RenderSettings settings);

// Band `band` of `band_rows` rows (the last may have fewer) of the poster `whole`
// (poster_settings), rendered with all its samples and read back with `passes` into `image`.
// The same pixels whichever process renders it: MPI jobs share a poster's bands out this way.
void render_poster_band(RenderWorker& renderer, const SceneInfo& info, const SceneState& state,
                        const RenderSettings& whole, int band_rows, int band, Readback passes,
                        FrameImage& image);

struct PosterResult {
  RayCounts rays;  // over the whole image
  Precision precision = Precision::Float;
  int lanes = 0;
  int bands = 0;
};

// Renders `settings`' size of the scene in bands of at most `band_pixels` pixels (whole rows;
// at least one row) and writes it to `file` as PNG, or as OpenEXR when it is named *.exr,
// atomically. `progress(done, total)` is
// called after each band. Throws std::runtime_error (rendering or writing); nothing is left at
// `file` then.
PosterResult render_poster(RenderWorker& worker, const SceneInfo& info, const SceneState& state,
                           RenderSettings settings, const std::filesystem::path& file,
                           uint64_t band_pixels = kPosterBandPixels,
                           const std::function<void(int, int)>& progress = nullptr);
// The same with `band_rows` rows a band (at least 1).
PosterResult render_poster_in_rows(RenderWorker& worker, const SceneInfo& info,
                                   const SceneState& state, RenderSettings settings,
                                   const std::filesystem::path& file, int band_rows,
                                   const std::function<void(int, int)>& progress = nullptr);

// Adds a band's primary rays to `counts`.
void add_ray_counts(const FrameImage& band, RayCounts& counts);

}  // namespace fr
