#include "cli/preset_files.hpp"

#include "cli/options.hpp"
#include "import/fract_file.hpp"
#include "io/echo.hpp"

#include <cctype>

namespace fr {

bool is_preset_path(const std::string& value) {
  auto ends_with = [&](const std::string& suffix) {
    return value.size() >= suffix.size() &&
           value.compare(value.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with(".toml") || ends_with(".fract") || value.find('/') != std::string::npos ||
         value.find('\\') != std::string::npos;
}

std::string preset_id_from_file(const std::filesystem::path& file) {
  std::string id;
  for (unsigned char c : file.stem().string()) {
    if (std::isalnum(c)) {
      id += static_cast<char>(std::tolower(c));
    } else if (!id.empty() && id.back() != '_' && c < 0x80) {
      id += '_';
    }
    if (id.size() >= 60) break;
  }
  while (!id.empty() && id.back() == '_') id.pop_back();
  if (id.empty() || !(id[0] >= 'a' && id[0] <= 'z')) id = "imported_" + id;
  return id;
}

Mb2Import import_fract_file(const std::filesystem::path& file) {
  const FractFile parsed = load_fract(file);
  return import_fract(parsed, file.stem().string());
}

Preset preset_from_path(const std::string& value) {
  const std::filesystem::path file = value;
  const std::string id = preset_id_from_file(file);
  std::vector<std::string> problems;
  if (file.extension() == ".fract") {
    Mb2Import imported;
    try {
      imported = import_fract_file(file);
    } catch (const FractError& e) {
      throw UsageError(std::string("--preset: ") + e.what());
    }
    if (!imported.faithful()) {
      // One line, as every usage error: the reasons joined.
      std::string message = "--preset " + echo(value) + ": cannot be imported faithfully: ";
      const std::vector<std::string> why = imported.refusals();
      for (size_t i = 0; i < why.size(); ++i) message += (i ? "; " : "") + why[i];
      throw UsageError(message);
    }
    if (auto p = preset_from_text(imported.preset_toml, file, id, &problems)) return *p;
  } else if (auto p = read_preset_file(file, id, &problems)) {
    return *p;
  }
  throw UsageError("--preset: " +
                   (problems.empty() ? echo(value) + ": not a preset" : problems.front()));
}

}  // namespace fr
