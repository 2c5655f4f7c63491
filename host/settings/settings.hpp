// settings.hpp — settings from built-in defaults, then a TOML file, then the command line.
//
// Every key a file may hold is listed in settings_table.cpp (known_setting_keys); any other key is
// an error that names the nearest known one, so a typo never silently falls back to a default.
#pragma once

#include "plugin/plugin_policy.hpp"
#include "render/render_settings.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fr {

// The explorer's own settings: window, frame rate and quality, controls and key bindings.
struct ExplorerSettings {
  int window_width_px = 1280;
  int window_height_px = 720;
  bool fullscreen = false;
  double target_fps = 30;  // held while the camera moves
  // While moving, trace a lattice of the pixels and carry the rest from earlier frames
  // (app/temporal_reuse.hpp) rather than render fewer pixels and stretch them.
  bool temporal = false;
  int full_quality_samples = 8;  // accumulated once it stops ("quality" presets: 2, 8, 32)
  // Accumulated once it stops when render.integrator is "path" (flying stays on "fast").
  int path_samples = 256;
  bool denoise = true;  // the path-traced preview's first samples filtered (render.denoise)
  double mouse_sensitivity_deg_per_px = 0.15;
  bool invert_y = false;
  double speed = 1.0;  // fly speed, in distances-to-the-surface per second
  std::map<std::string, std::string> key_bindings;  // key name -> action name, over the defaults
};

// What fractalis keeps in its cache folder (io/cache_dirs.hpp).
struct CacheSettings {
  int kernel_cache_mib = 512;  // compiled kernels, trimmed least recently used first
};

struct Settings {
  std::vector<std::filesystem::path> plugin_folders;  // searched before the built-in folders
  PluginPolicy plugins;                               // isolation, time limits, permissions
  std::string device;                                 // selector, see select_device
  RenderSettings render;
  ExplorerSettings explorer;
  CacheSettings cache;
};

// One problem in a settings file: "FILE:LINE: key 'render.lanes': expected one of 1, 4, 8, 16".
struct SettingsProblem {
  std::string file;
  int line = 0;
  std::string key;
  std::string message;
  std::string to_string() const;  // line 0 (command line) is left out
};

// The user's file: $XDG_CONFIG_HOME/fractalis/config.toml (or ~/.config/...), if it exists.
std::optional<std::filesystem::path> user_settings_file();
// Where the user's file is or would be (empty when neither XDG_CONFIG_HOME nor HOME is set).
std::filesystem::path user_settings_path();

// Reads `file` over `settings`. Values that are wrong are reported and leave that setting as it
// was; the rest still apply. Returns the problems (empty when the file is fine).
std::vector<SettingsProblem> load_settings_file(const std::filesystem::path& file,
                                                Settings& settings);

// The same for settings text already in memory; `name` stands for the file in messages.
std::vector<SettingsProblem> load_settings_text(const std::string& text, const std::string& name,
                                                Settings& settings);

// Applies one "key=value" from the command line (--set), checked exactly like a file's.
std::vector<SettingsProblem> apply_setting_override(const std::string& assignment,
                                                    Settings& settings);

// The settings as a TOML file that load_settings_file reads back to the same values, every key
// with its comment, `header` as the file's opening comment (the explorer writes the user's file
// with it, atomically).
std::string format_settings_toml(const Settings& settings, const std::string& header);
// config/default.toml: the built-in defaults, written out.
std::string default_settings_toml();

// The known key closest to `key` by edit distance (for "did you mean"); "" for a key of over 200
// characters.
std::string nearest_known_key(const std::string& key);
std::vector<std::string> known_setting_keys();

}  // namespace fr
