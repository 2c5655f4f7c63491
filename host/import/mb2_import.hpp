// mb2_import.hpp — a Mandelbulber2 settings file as a Fractalis preset for the `mandelbulber`
// scene (plugins/mandelbulber/): its formulas, hybrid sequence, Julia constant and bailout as the
// scene's parameters, its camera as the preset's view, its quality and effects as settings. Every
// key that changes the shape is mapped exactly or the import is refused with one reason per item
// ("slot 2: formula 16 (box_fold_bulb_pow2) is not supported"); what changes only the look is
// approximated or ignored, and each such key is named. docs/mandelbulber2.md has the tables.
#pragma once

#include "import/fract_file.hpp"

#include <string>
#include <vector>

namespace fr {

struct ImportNote {
  enum class Kind {
    Mapped,        // carried over as it is
    Approximated,  // carried over as the nearest Fractalis has
    Ignored,       // changes the look, not the shape; not carried over
    Refused        // changes the shape and cannot be carried over: the import fails
  };
  Kind kind;
  std::string item;  // the key or slot it is about ("slot 2", "DOF_enabled")
  std::string text;
};

const char* import_note_kind_name(ImportNote::Kind kind);  // "mapped", "approximated", ...

struct Mb2Import {
  std::vector<ImportNote> notes;
  std::string preset_toml;  // the preset, when nothing was refused ("" otherwise)
  bool faithful() const;    // nothing refused
  // The refusals' items and texts, one line each ("slot 2: formula 16 ... is not supported").
  std::vector<std::string> refusals() const;
};

constexpr const char* kMb2SceneId = "mandelbulber";
constexpr double kMb2NewestVersion = 2.20;  // the format read; newer files changed units (fov)

// Maps the parsed file. `name` is the preset's display name. Values that cannot be read are a
// FractError (file, line, key); what Fractalis cannot render is a Refused note.
Mb2Import import_fract(const FractFile& file, const std::string& name);

}  // namespace fr
