// thumbnail_cache.hpp — the scene browser's pictures on disk, so that a second start shows them
// at once: one PNG per picture in $XDG_CACHE_HOME/fractalis/thumbnails, named by a digest of
// everything the picture depends on (thumbnail_key). A changed scene, preset, setting or renderer
// is a new name; an old file is never shown for it. `fractalis cache --clear` empties the folder.
//
// Nothing in the folder is trusted: a file that is not a readable PNG of the size asked for is
// said once, removed and rendered again; a folder that cannot be written is said once, and the
// pictures of this session are then kept in memory only.
#pragma once

#include "image/png_read.hpp"
#include "render/render_settings.hpp"
#include "scene/scene_data.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fr {

// Sixteen hex digits over the scene's render kernel (its DE, surface, parameter table and the
// renderer's stages, as assembled for `settings`), its parameter values, camera, lights and
// bounding radius, every render setting, and the picture's size.
std::string thumbnail_key(const SceneInfo& info, const SceneState& state,
                          const RenderSettings& settings);

class ThumbnailCache {
 public:
  // `folder` empty: no disk cache (every picture is rendered, kept in memory).
  explicit ThumbnailCache(std::filesystem::path folder);

  // The picture stored under `key` at width_px x height_px, or nullopt (none, or a bad file,
  // which is then removed and named in problems()).
  std::optional<RgbaImage> load(const std::string& key, int width_px, int height_px);
  // Writes the picture (atomically); a failure is named once in problems().
  void store(const std::string& key, const RgbaImage& image);

  const std::filesystem::path& folder() const { return folder_; }
  // What went wrong with the folder, once each, in order (the browser shows them).
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::filesystem::path file_for(const std::string& key) const;

  std::filesystem::path folder_;
  bool writable_ = true;  // false after a failed write: not tried again this session
  std::vector<std::string> problems_;
};

}  // namespace fr
