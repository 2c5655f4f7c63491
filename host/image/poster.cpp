#include "image/poster.hpp"

#include "image/band_writer.hpp"

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

RenderSettings poster_settings(RenderWorker& worker, const SceneInfo& info, const SceneState& state,
                               RenderSettings settings) {
  if (settings.width_px < 1 || settings.height_px < 1)
    throw std::runtime_error("image size " + std::to_string(settings.width_px) + "x" +
                             std::to_string(settings.height_px) + " has no pixels");
  settings.window = {};
  settings.precision = worker.prepare(info, state, settings);
  return settings;
}

void render_poster_band(RenderWorker& renderer, const SceneInfo& info, const SceneState& state,
                        const RenderSettings& whole, int band_rows, int band, Readback passes,
                        FrameImage& image) {
  const int y0 = band * band_rows;
  RenderSettings s = whole;
  s.height_px = std::min(band_rows, whole.height_px - y0);
  s.window = {whole.width_px, whole.height_px, 0, y0};
  for (int i = 0; i < std::max(1, s.samples); ++i)
    renderer.render_sample(info, state, s, i, passes);
  renderer.finish(s, passes, image);
}

void add_ray_counts(const FrameImage& band, RayCounts& counts) {
  const RayCounts c = count_rays(band);
  counts.hit += c.hit;
  counts.miss += c.miss;
  counts.out_of_steps += c.out_of_steps;
  counts.inside += c.inside;
}

PosterResult render_poster(RenderWorker& worker, const SceneInfo& info, const SceneState& state,
                           RenderSettings settings, const std::filesystem::path& file,
                           uint64_t band_pixels, const std::function<void(int, int)>& progress) {
  return render_poster_in_rows(worker, info, state, settings, file,
                               poster_band_rows(settings.width_px, settings.height_px, band_pixels),
                               progress);
}

PosterResult render_poster_in_rows(RenderWorker& worker, const SceneInfo& info,
                                   const SceneState& state, RenderSettings settings,
                                   const std::filesystem::path& file, int band_rows,
                                   const std::function<void(int, int)>& progress) {
  const RenderSettings whole = poster_settings(worker, info, state, settings);
  band_rows = std::max(band_rows, 1);
  PosterResult result;
  result.precision = whole.precision;
  result.bands = (whole.height_px + band_rows - 1) / band_rows;
  BandWriter writer(file, whole.width_px, whole.height_px);
  FrameImage band;
  for (int b = 0; b < result.bands; ++b) {
    render_poster_band(worker, info, state, whole, band_rows, b, writer.passes(), band);
    writer.write_rows(band);
    add_ray_counts(band, result.rays);
    result.lanes = band.lanes;
    if (progress) progress(b + 1, result.bands);
  }
  writer.finish();
  return result;
}

}  // namespace fr
