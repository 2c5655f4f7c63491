#include "image/poster.hpp"

#include "image/band_writer.hpp"
#include "render/precision.hpp"

#include <algorithm>
#include <stdexcept>

namespace fr {

int poster_band_rows(int width_px, int height_px, uint64_t band_pixels) {
  return static_cast<int>(
      std::clamp<uint64_t>(band_pixels / static_cast<uint64_t>(std::max(width_px, 1)), 1,
                           static_cast<uint64_t>(std::max(height_px, 1))));
}

uint64_t poster_band_pixels(const std::filesystem::path& file) {
  return is_exr_file_name(file) ? kExrPosterBandPixels : kPosterBandPixels;
}

PosterResult render_poster(ClRuntime& runtime, const SceneInfo& info, const SceneState& state,
                           RenderSettings settings, const std::filesystem::path& file,
                           uint64_t band_pixels, const std::function<void(int, int)>& progress) {
  const int width = settings.width_px, height = settings.height_px;
  if (width < 1 || height < 1)
    throw std::runtime_error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " has no pixels");
  PosterResult result;
  settings.window = {};
  settings.precision = resolve_precision(runtime, info, state, settings);
  result.precision = settings.precision;
  const int band_rows = poster_band_rows(width, height, band_pixels);
  result.bands = (height + band_rows - 1) / band_rows;

  BandWriter writer(file, width, height);
  Renderer renderer(runtime);
  FrameImage band;
  for (int b = 0; b < result.bands; ++b) {
    const int y0 = b * band_rows, rows = std::min(band_rows, height - y0);
    RenderSettings s = settings;
    s.height_px = rows;
    s.window = {width, height, 0, y0};
    for (int i = 0; i < std::max(1, s.samples); ++i)
      renderer.render_sample(info, state, s, i, writer.passes());
    renderer.finish(s, writer.passes(), band);
    writer.write_rows(band);
    const RayCounts counts = count_rays(band);
    result.rays.hit += counts.hit;
    result.rays.miss += counts.miss;
    result.rays.out_of_steps += counts.out_of_steps;
    result.rays.inside += counts.inside;
    result.lanes = band.lanes;
    if (progress) progress(b + 1, result.bands);
  }
  writer.finish();
  return result;
}

}  // namespace fr
