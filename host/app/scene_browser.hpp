// scene_browser.hpp — the explorer's scene browser without its drawing (ui/scene_browser_view.hpp
// draws it): every scene of the library and every preset as an entry with a picture, name,
// family and description, and every file that failed to load with why; a search over names,
// ids, tags and descriptions; a selection that arrows move; and the pictures, from the
// thumbnail cache or rendered in the background (app/thumbnail_renderer.hpp).
#pragma once

#include "app/explorer.hpp"
#include "app/thumbnail_cache.hpp"
#include "app/thumbnail_renderer.hpp"
#include "path/preset.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fr {

struct BrowserEntry {
  std::string scene_id;   // "" for a file that failed to load
  std::string preset_id;  // "" for the scene's own default view
  std::string title;      // "Mandelbox", "Mandelbox: Spiky ball", or the failed file's name
  std::string family;     // the first tag
  std::string description;
  std::string error;       // why the file failed to load, or why its picture failed
  std::string search_text;  // lower case: id, preset id, title, tags, description
  std::string thumbnail_key;  // "" for a failed file
  bool preparing = false;     // its scene waits for its test render: no picture yet
};

// Does every word of `query` (split at spaces, case ignored) occur in `search_text`?
bool browser_matches(const std::string& search_text, const std::string& query);

struct SceneBrowserOptions {
  int thumbnail_width_px = 192, thumbnail_height_px = 108;
  std::filesystem::path cache_folder;  // "" : no disk cache
};

class SceneBrowser {
 public:
  // `device` and `limits`: for the thumbnails' own render worker.
  // Preset files that failed to load (`preset_problems`) are shown as failed entries.
  SceneBrowser(std::vector<Preset> presets, std::vector<PresetProblem> preset_problems,
               const SceneBrowserOptions& options,
               const DeviceInfo& device, const RenderWorkerLimits& limits);

  bool visible() const { return visible_; }
  void set_visible(bool on);

  // Each frame while visible: the entries follow the library (a scene added, reloaded or failed
  // while the browser is open appears), pictures are looked up in the cache, the missing ones of
  // the visible entries are asked of the renderer, and finished ones are taken in.
  void update(SceneLibrary& library, const RenderSettings& settings);

  const std::vector<BrowserEntry>& entries() const { return entries_; }
  // Indices into entries() that the query matches, in order.
  const std::vector<int>& shown() const { return shown_; }
  const std::string& query() const { return query_; }
  void set_query(const std::string& query);

  // The selection, as a position in shown() (-1 when nothing is shown). move() steps it by
  // `delta` positions, clamped to the list.
  int selected() const { return selected_; }
  void select(int position);
  void move(int delta);

  // The picture of an entry, or null while there is none yet (or it failed: entry.error).
  const RgbaImage* thumbnail(const BrowserEntry& entry) const;
  // Why an entry cannot be opened or has no picture ("" when it is fine).
  std::string failed_reason(const BrowserEntry& entry) const;
  // Pictures still to come for the shown entries.
  int pending() const;
  // Scenes of the library still waiting for their test render, and all of its scenes (as of the
  // last update), for "preparing scenes: 12 of 40".
  int preparing_scenes() const { return preparing_scenes_; }
  int library_scenes() const { return library_scenes_; }
  // Pictures rendered (not found in the cache) since the browser was made.
  int rendered() const { return rendered_; }
  const ThumbnailCache& cache() const { return cache_; }

  // Opens the shown entry at `position` in the explorer: switches to its scene and, for a preset,
  // applies its values and view. Closes the browser. Returns false (and sets *error) for a failed
  // file or a preset that no longer applies.
  bool open(int position, Explorer& explorer, std::string* error);

 private:
  void rebuild(SceneLibrary& library, const RenderSettings& settings);
  void filter();

  std::vector<Preset> presets_;
  // The settings keys the preset opened last set (an imported file's [settings]), and the
  // settings from before it, to put back when something else is opened.
  std::vector<std::string> preset_setting_keys_;
  Settings settings_before_preset_;
  std::vector<PresetProblem> preset_problems_;
  SceneBrowserOptions options_;
  ThumbnailCache cache_;
  ThumbnailRenderer renderer_;
  bool visible_ = false;
  std::string library_signature_;  // the library's generation and the settings built from
  std::vector<BrowserEntry> entries_;
  std::vector<ThumbnailJob> jobs_;  // by entry: what its picture is rendered from
  std::vector<int> shown_;
  std::string query_;
  int selected_ = -1;
  std::map<std::string, RgbaImage> images_;         // by thumbnail key
  std::map<std::string, std::string> failed_;       // by thumbnail key: why
  std::map<std::string, bool> requested_;           // by thumbnail key
  int rendered_ = 0;
  int preparing_scenes_ = 0, library_scenes_ = 0;
};

}  // namespace fr
