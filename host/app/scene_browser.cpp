#include "app/scene_browser.hpp"

#include "io/fnv1a.hpp"
#include "io/printable.hpp"
#include "plugin/scene_instance.hpp"
#include "settings/settings.hpp"
#include "settings/settings_table.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace fr {
namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

bool browser_matches(const std::string& search_text, const std::string& query) {
  std::istringstream words(lower(query));
  std::string word;
  while (words >> word)
    if (search_text.find(word) == std::string::npos) return false;
  return true;
}

SceneBrowser::SceneBrowser(std::vector<Preset> presets,
                           std::vector<PresetProblem> preset_problems,
                           const SceneBrowserOptions& options, const DeviceInfo& device,
                           const RenderWorkerLimits& limits)
    : presets_(std::move(presets)), preset_problems_(std::move(preset_problems)),
      options_(options), cache_(options.cache_folder),
      renderer_(device, limits) {}

void SceneBrowser::set_visible(bool on) {
  visible_ = on;
  // Closed, it takes no CPU from flying: the pictures not started wait for the next opening.
  if (!on) {
    renderer_.clear();
    for (auto it = requested_.begin(); it != requested_.end();)
      it = images_.count(it->first) || failed_.count(it->first) ? std::next(it)
                                                                 : requested_.erase(it);
  }
}

void SceneBrowser::rebuild(SceneLibrary& library, const RenderSettings& settings) {
  entries_.clear();
  jobs_.clear();
  RenderSettings picture = settings;
  picture.width_px = options_.thumbnail_width_px;
  picture.height_px = options_.thumbnail_height_px;
  picture.window = {};
  picture.samples = 1;
  picture.outputs = Readback::Display;
  for (const SceneSlot& slot : library.slots()) {
    const SceneInfo& info = slot.scene->info;
    const std::vector<std::string> tags = scene_tags(info);
    std::string tag_text;
    for (const std::string& t : tags) tag_text += t + " ";
    BrowserEntry entry;
    entry.scene_id = info.id;
    entry.title = info.name.empty() ? info.id : info.name;
    entry.family = tags.empty() ? "" : tags.front();
    entry.description = info.description;
    entry.search_text = lower(info.id + " " + info.name + " " + tag_text + info.description);
    entry.preparing = slot.preparing;
    if (slot.refused) entry.error = slot.error;
    ThumbnailJob job{"", slot.scene, make_default_state(info), picture};
    std::vector<std::pair<BrowserEntry, ThumbnailJob>> rows;
    rows.emplace_back(entry, job);
    for (const Preset& preset : presets_) {
      if (preset.scene_id != info.id) continue;
      BrowserEntry p = entry;
      p.preset_id = preset.id;
      p.title = entry.title + ": " + preset.name;
      p.description = preset.description;
      p.search_text = lower(preset.id + " " + preset.name + " " + preset.description + " ") +
                      entry.search_text;
      ThumbnailJob pj = job;
      std::vector<std::string> problems = apply_preset(preset, info, pj.state);
      {
        // The preset's settings (an imported file's detail, mirror) show in its picture too.
        Settings with_preset;
        with_preset.render = pj.settings;
        for (std::string& s : apply_preset_settings(preset, with_preset)) problems.push_back(s);
        pj.settings = with_preset.render;
      }
      if (!problems.empty()) p.error = problems.front();
      rows.emplace_back(p, pj);
    }
    for (auto& [e, j] : rows) {
      try {
        if (e.error.empty()) e.thumbnail_key = thumbnail_key(info, j.state, j.settings);
      } catch (const std::exception& ex) {
        e.error = ex.what();  // a scene source that no longer assembles
      }
      j.key = e.thumbnail_key;
      entries_.push_back(std::move(e));
      jobs_.push_back(std::move(j));
    }
  }
  // Presets whose scene is not here: shown, with why, so a typo in `scene` is found.
  for (const Preset& preset : presets_) {
    if (library.find(preset.scene_id) >= 0) continue;
    BrowserEntry e;
    e.preset_id = preset.id;
    e.title = preset.name;
    e.description = preset.description;
    e.error = printable(preset.file.string()) + ": for scene '" + printable(preset.scene_id) +
              "', which is not loaded";
    e.search_text = lower(preset.id + " " + preset.name + " " + preset.description);
    entries_.push_back(std::move(e));
    jobs_.emplace_back();
  }
  // Files that gave no scene or preset: shown with why, so a broken one is found.
  const auto failed = [&](const std::filesystem::path& file, const std::string& why) {
    BrowserEntry e;
    e.title = printable(file.filename().string());
    e.family = "failed";
    e.error = why;
    e.search_text = lower(e.title + " failed " + why);
    entries_.push_back(std::move(e));
    jobs_.emplace_back();
  };
  for (const PresetProblem& problem : preset_problems_) failed(problem.file, problem.message);
  for (const SceneEvent& event : library.failed_files())
    if (std::none_of(library.slots().begin(), library.slots().end(),
                     [&](const SceneSlot& slot) { return slot.scene->file == event.file; }))
      failed(event.file, event.reason);  // (a refused slot is its own entry, above)
  filter();
}

void SceneBrowser::update(SceneLibrary& library, const RenderSettings& settings) {
  for (ThumbnailResult& done : renderer_.take_done()) {
    if (!done.error.empty()) {
      failed_[done.key] = done.error;
      continue;
    }
    ++rendered_;
    cache_.store(done.key, done.image);
    images_[done.key] = std::move(done.image);
  }
  preparing_scenes_ = library.preparing();
  library_scenes_ = static_cast<int>(library.slots().size());
  if (!visible_) return;
  // Built again when the library changed (a scene added, reloaded, failed or removed) or the
  // settings the pictures are rendered with did.
  Settings all;
  all.render = settings;
  const std::string signature = std::to_string(library.generation()) + " " +
                                hex16(fnv1a(format_settings_toml(all, "")));
  if (signature != library_signature_) {
    library_signature_ = signature;
    rebuild(library, settings);
  }
  // The selected entry first, then the rest of what is shown, in order.
  std::vector<int> order;
  if (selected_ >= 0) order.push_back(shown_[selected_]);
  order.insert(order.end(), shown_.begin(), shown_.end());
  // Requested newest first by the renderer: pushed in reverse, the first comes first.
  std::vector<int> to_render;
  for (int index : order) {
    const std::string& key = entries_[index].thumbnail_key;
    // (A scene is rendered only once its test render passed: its DE might never return.)
    if (entries_[index].preparing) continue;
    if (key.empty() || images_.count(key) || failed_.count(key) || requested_.count(key)) continue;
    if (auto image =
            cache_.load(key, options_.thumbnail_width_px, options_.thumbnail_height_px)) {
      images_[key] = std::move(*image);
      continue;
    }
    requested_[key] = true;
    to_render.push_back(index);
  }
  for (auto it = to_render.rbegin(); it != to_render.rend(); ++it) renderer_.request(jobs_[*it]);
}

void SceneBrowser::filter() {
  const int previous = selected_ >= 0 && selected_ < int(shown_.size()) ? shown_[selected_] : -1;
  shown_.clear();
  for (size_t i = 0; i < entries_.size(); ++i)
    if (browser_matches(entries_[i].search_text, query_)) shown_.push_back(static_cast<int>(i));
  const auto kept = std::find(shown_.begin(), shown_.end(), previous);
  selected_ = shown_.empty() ? -1 : kept != shown_.end() ? int(kept - shown_.begin()) : 0;
}

void SceneBrowser::set_query(const std::string& query) {
  if (query == query_) return;
  query_ = query;
  filter();
}

void SceneBrowser::select(int position) {
  if (shown_.empty()) return;
  selected_ = std::clamp(position, 0, static_cast<int>(shown_.size()) - 1);
}

void SceneBrowser::move(int delta) {
  select(selected_ + delta);
}

const RgbaImage* SceneBrowser::thumbnail(const BrowserEntry& entry) const {
  const auto it = images_.find(entry.thumbnail_key);
  return it == images_.end() ? nullptr : &it->second;
}

int SceneBrowser::pending() const {
  int count = 0;
  for (int index : shown_) {
    const std::string& key = entries_[index].thumbnail_key;
    count += !key.empty() && !images_.count(key) && !failed_.count(key);
  }
  return count;
}

bool SceneBrowser::open(int position, Explorer& explorer, std::string* error) {
  if (position < 0 || position >= static_cast<int>(shown_.size())) {
    *error = "nothing to open";
    return false;
  }
  const BrowserEntry& entry = entries_[shown_[position]];
  const int slot = explorer.library().find(entry.scene_id);
  if (entry.scene_id.empty() || slot < 0) {
    *error = entry.title + ": " + (entry.error.empty() ? "not loaded" : entry.error);
    return false;
  }
  explorer.select_scene(slot);
  // The settings the last preset opened here set go back to what they were before it.
  for (const std::string& key : preset_setting_keys_)
    if (const SettingSpec* spec = find_setting(key))
      spec->set(explorer.settings(), spec->get(settings_before_preset_));
  preset_setting_keys_.clear();
  if (!entry.preset_id.empty()) {
    const auto preset = find_preset(presets_, entry.preset_id);
    SceneSlot& current = explorer.current();
    std::vector<std::string> problems =
        preset ? apply_preset(*preset, current.scene->info, current.state)
               : std::vector<std::string>{"preset '" + entry.preset_id + "' is gone"};
    if (preset && problems.empty()) {
      settings_before_preset_ = explorer.settings();
      problems = apply_preset_settings(*preset, explorer.settings(), &preset_setting_keys_);
    }
    if (!problems.empty()) {
      *error = problems.front();
      return false;
    }
  }
  explorer.mark_changed();
  set_visible(false);
  return true;
}

std::string SceneBrowser::failed_reason(const BrowserEntry& entry) const {
  if (!entry.error.empty()) return entry.error;
  const auto it = failed_.find(entry.thumbnail_key);
  return it == failed_.end() ? "" : "no picture: " + it->second;
}

}  // namespace fr
