// fract_file.hpp — Mandelbulber2's settings file (`.fract`) read as text: its version, and the
// `name value;` lines of its [main_parameters] and [fractal_1]..[fractal_9] sections, each with
// its line number. Nothing here knows what a key means (fract_values.hpp reads values,
// mb2_defaults.hpp knows the defaults, mb2_import.hpp maps a file to a preset).
//
// The format, as Mandelbulber2 2.x writes it:
//
//   # Mandelbulber settings file
//   # version 2.20
//   # only modified parameters          (absent keys take the defaults)
//   [main_parameters]
//   camera 1,5 -2,66 1,77;              (the saving machine's decimal separator: comma or dot)
//   formula_1 8;
//   [fractal_1]
//   mandelbox_scale -1,5;
//   [keyframes] / [frames] / [description]   (animation data and free text: skipped)
//
// A file that is not such a file (no header, binary bytes, a line over kMaxFractLineChars, a
// `name value;` line that is malformed, a key given twice with different values) is a
// FractError naming the file, the line and the key.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

namespace fr {

constexpr size_t kMaxFractBytes = 4u << 20;  // the largest example is 30 KB
constexpr size_t kMaxFractLineChars = 4096;  // a palette or a keyframe row fits easily
constexpr int kFractFormulaSlots = 9;        // [fractal_1]..[fractal_9]

struct FractError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FractEntry {
  std::string value;  // as written, without the `;` and the spaces around it
  int line = 0;
};

struct FractFile {
  std::filesystem::path file;                                     // for messages
  double version = 0;                                             // `# version 2.20` -> 2.20
  bool only_modified = false;                                     // `# only modified parameters`
  std::map<std::string, FractEntry> main;                         // [main_parameters]
  std::map<std::string, FractEntry> fractal[kFractFormulaSlots];  // [fractal_1] at 0
};

// Parses the text of a settings file; `file` names it in errors.
FractFile parse_fract(const std::string& text, const std::filesystem::path& file);

// Reads and parses a file (at most kMaxFractBytes).
FractFile load_fract(const std::filesystem::path& file);

// "FILE:LINE: key: " — the start of a message about an entry.
std::string fract_where(const FractFile& f, int line, const std::string& key = "");

}  // namespace fr
