#include "app/thumbnail_cache.hpp"

#include "image/png_write.hpp"
#include "io/fnv1a.hpp"
#include "render/kernel_assembly.hpp"
#include "settings/settings.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace fr {
namespace {

template <typename T>
uint64_t hash_bytes(const T* data, size_t count, uint64_t h) {
  return fnv1a(std::string_view(reinterpret_cast<const char*>(data), count * sizeof(T)), h);
}

}  // namespace

std::string thumbnail_key(const SceneInfo& info, const SceneState& state,
                          const RenderSettings& settings) {
  uint64_t h = fnv1a("fractalis thumbnail 1\n");
  // The kernel as a one-lane build of it would be: the DE, the surface, the generated parameter
  // struct (specialised values baked in) and every stage's code and mode.
  const AssembledKernel kernel =
      assemble_render_kernel(info, state.params, make_kernel_config(info, settings, 1));
  h = fnv1a(kernel.source, h);
  h = fnv1a(kernel.build_options, h);
  // Every setting (the effects' strengths, exposure, colours, ...), as the settings file has them.
  Settings all;
  all.render = settings;
  h = fnv1a(format_settings_toml(all, ""), h);
  h = fnv1a(std::to_string(settings.width_px) + "x" + std::to_string(settings.height_px) + "x" +
                std::to_string(settings.samples),
            h);
  if (!state.params.empty()) h = hash_bytes(state.params.data(), state.params.size(), h);
  h = hash_bytes(&state.camera, 1, h);
  if (!state.lights.empty()) h = hash_bytes(state.lights.data(), state.lights.size(), h);
  h = hash_bytes(&state.bounding_radius, 1, h);
  return hex16(h);
}

ThumbnailCache::ThumbnailCache(std::filesystem::path folder) : folder_(std::move(folder)) {
  writable_ = !folder_.empty();
}

std::filesystem::path ThumbnailCache::file_for(const std::string& key) const {
  return folder_ / (key + ".png");
}

std::optional<RgbaImage> ThumbnailCache::load(const std::string& key, int width_px,
                                              int height_px) {
  if (folder_.empty()) return std::nullopt;
  // Keys are ours (hex16), never a path: a key with anything else is not looked up.
  if (key.empty() || !std::all_of(key.begin(), key.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || (c >= 'a' && c <= 'f');
      }))
    return std::nullopt;
  const std::filesystem::path file = file_for(key);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  RgbaImage image;
  std::string error;
  const bool read = read_png_rgba8(file, 4096, &image, &error);
  if (read && (image.width_px != width_px || image.height_px != height_px))
    error = file.string() + ": " + std::to_string(image.width_px) + "x" +
            std::to_string(image.height_px) + " pixels, not the " + std::to_string(width_px) +
            "x" + std::to_string(height_px) + " of its name";
  if (!error.empty()) {
    std::filesystem::remove(file, ec);
    problems_.push_back("thumbnail cache: " + error + "; removed, rendered again");
    return std::nullopt;
  }
  return image;
}

void ThumbnailCache::store(const std::string& key, const RgbaImage& image) {
  if (!writable_) return;
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  std::string error;
  if (ec)
    error = "cannot make " + folder_.string() + ": " + ec.message();
  else if (!write_png_atomic(file_for(key), image.width_px, image.height_px, image.rgba8, &error))
    error = error.empty() ? "cannot write " + file_for(key).string() : error;
  else
    return;
  writable_ = false;
  problems_.push_back("thumbnail cache: " + error +
                      "; this session's thumbnails are kept in memory only");
}

}  // namespace fr
