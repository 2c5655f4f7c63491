// preset_files.hpp — presets named by their file rather than their id: a preset's TOML file
// anywhere, or a Mandelbulber2 settings file (.fract) imported into one (import/mb2_import.hpp).
// `--preset FILE` on every command that takes a preset, and `fractalis import`, go through here.
#pragma once

#include "import/mb2_import.hpp"
#include "path/preset.hpp"

#include <filesystem>
#include <string>

namespace fr {

// Whether --preset's value names a file (ends in .toml or .fract, or has a folder in it).
bool is_preset_path(const std::string& value);

// A preset id made from a file name: lower case, [a-z0-9_-], starting with a letter
// ("Menger sponge 001.fract" -> "menger_sponge_001").
std::string preset_id_from_file(const std::filesystem::path& file);

// The .fract file imported (a FractError for a file that cannot be read as one).
Mb2Import import_fract_file(const std::filesystem::path& file);

// The preset in the file; a UsageError names what is wrong (for a .fract file, every reason it
// cannot be imported, on one line).
Preset preset_from_path(const std::string& value);

}  // namespace fr
