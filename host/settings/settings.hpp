// settings.hpp — settings from built-in defaults, then a TOML file, then the command line.
//
// Every key a file may hold is listed in settings.cpp (known_setting_keys); any other key is an
// error that names the nearest known one, so a typo never silently falls back to a default.
#pragma once

#include "render/render_settings.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fr {

struct Settings {
  std::vector<std::filesystem::path> plugin_folders;  // searched before the built-in folders
  std::string device;                                 // selector, see select_device
  RenderSettings render;
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

// Reads `file` over `settings`. Values that are wrong are reported and leave that setting as it
// was; the rest still apply. Returns the problems (empty when the file is fine).
std::vector<SettingsProblem> load_settings_file(const std::filesystem::path& file,
                                                Settings& settings);

// Applies one "key=value" from the command line (--set), checked exactly like a file's.
std::vector<SettingsProblem> apply_setting_override(const std::string& assignment,
                                                    Settings& settings);

// The known key closest to `key` by edit distance (for "did you mean").
std::string nearest_known_key(const std::string& key);
std::vector<std::string> known_setting_keys();

}  // namespace fr
