// preset.hpp — presets: a named set of parameter values and a view for a scene, from a TOML file
// (as Fragmentarium's #preset and Mandelbulber2's example settings).
//
//   scene = "mandelbox"                 # the scene it is for (required)
//   name = "Spiky ball"                 # display name (required)
//   description = "Scale -1.5: ..."     # one sentence (optional)
//   [params]                            # values by key, as in a camera path (choices by name)
//   scale = -1.5
//   [camera]                            # optional; any of eye, target, up, fov_deg
//   eye = [9.0, 6.0, 10.0]              # (or decimal strings, for a deep view's 34 digits:
//   target = [0.0, 0.0, 0.0]            # ["5.908838584519028311238859964040553", ...])
//   [[lights]]                          # optional; lights in place of the scene's first ones,
//   direction = [0.3, -0.8, -0.5]       # in order: a directional light (the way it travels), or
//   color = [1.0, 0.9, 0.8]             # with `position` a point light (and its attenuation a
//   intensity = 1.3                     # and falloff e: intensity / (1 + a d^e)); colour in
//                                       # linear RGB; an empty [[lights]] keeps the scene's
//   [settings]                          # optional; render.* settings as --set takes them
//   "render.hit_threshold_k" = 2.0      # (an imported file's quality and effects)
//
// A preset's id is its file's name without ".toml": [a-z][a-z0-9_-]*, unique over all folders
// (the first folder wins; a later file with the same id is reported, not used). Presets live in
// a `presets` folder inside each plugin folder; the in-tree ones beside their scene
// (plugins/ID/presets/) and the user's in their scene folder's presets/.
#pragma once

#include "scene/scene_data.hpp"
#include "settings/settings.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fr {

struct Preset {
  std::string id;        // the file's stem
  std::string scene_id;  // `scene`
  std::string name;
  std::string description;
  std::filesystem::path file;
  std::string text;  // the whole file, for applying to the scene's parameter table
};

struct PresetProblem {
  std::filesystem::path file;
  std::string message;  // "FILE:LINE: what" already, or "FILE: what"
};

// Every preset in `folders`/presets/*.toml, sorted by id. A file that cannot be read, is not
// valid TOML, lacks `scene` or `name`, has a key it should not, or repeats an id goes to
// `problems` (with file and line) and is left out. At most kMaxPresetBytes a file.
std::vector<Preset> load_presets(const std::vector<std::filesystem::path>& plugin_folders,
                                 std::vector<PresetProblem>* problems);

constexpr size_t kMaxPresetBytes = 64 * 1024;

// A preset from its text (`file` names it in problems, `id` is its id); nullopt with problems
// ("FILE:LINE: what") when it is not a preset.
std::optional<Preset> preset_from_text(const std::string& text, const std::filesystem::path& file,
                                       const std::string& id, std::vector<std::string>* problems);
// The same, read from a file (at most kMaxPresetBytes).
std::optional<Preset> read_preset_file(const std::filesystem::path& file, const std::string& id,
                                       std::vector<std::string>* problems);

// A preset's text for a scene's state: its parameter values and its view (eye and target with
// every digit a pair holds), as a screenshot's view is saved beside it; preset_from_text reads it
// back to the same values.
std::string format_preset(const SceneInfo& scene, const SceneState& state, const std::string& name,
                          const std::string& description);

// The preset's [settings] as KEY and VALUE texts, as `--set KEY=VALUE` takes them (in the file's
// order); checking them is the settings table's (settings/settings.hpp). Only render.* keys: any
// other (plugins.isolation, say) is a problem and left out.
std::vector<std::pair<std::string, std::string>> preset_settings(const Preset& preset,
                                                                 std::vector<std::string>* problems);

// Applies the preset's [settings] over `settings`; each problem ("FILE: [settings] KEY: what")
// is returned and that setting left as it was. `applied`, when given, receives the keys set.
std::vector<std::string> apply_preset_settings(const Preset& preset, Settings& settings,
                                               std::vector<std::string>* applied = nullptr);

// Applies the preset's values and camera over `state` (which holds the scene's defaults or
// more). Every problem — a key the scene does not have, a value of the wrong type or outside its
// range, a choice's name that names nothing, a camera that cannot make rays — is returned as
// "FILE:LINE: what", and then `state` is left as it was.
std::vector<std::string> apply_preset(const Preset& preset, const SceneInfo& scene,
                                      SceneState& state);

// The preset with this id, or nullopt.
std::optional<Preset> find_preset(const std::vector<Preset>& presets, const std::string& id);

}  // namespace fr
