// `fractalis import FILE.fract [--out DIR]`: a Mandelbulber2 settings file as a preset of the
// `mandelbulber` scene, written to the user's presets folder (or DIR), with what was mapped,
// approximated, ignored and refused, by key. `fractalis import --check DIR`: every .fract file
// under DIR imported in memory, the refusals counted by reason (docs/mandelbulber2.md's table).
//
// Exit codes: 0 imported faithfully (or --check done), 1 refused (the reasons, one a line), 2 a
// file that is not a settings file, or bad usage.
#include "cli/commands.hpp"
#include "cli/preset_files.hpp"
#include "cli/scene_options.hpp"
#include "import/fract_file.hpp"
#include "io/atomic_file.hpp"
#include "io/echo.hpp"
#include "io/printable.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <ostream>

namespace fr {
namespace {

const char* const kUsage =
    "usage: fractalis import FILE.fract [--out DIR] [--force]\n"
    "       fractalis import --check DIR [--list]\n"
    "\n"
    "Imports a Mandelbulber2 settings file as a preset of the `mandelbulber` scene (its formulas,\n"
    "hybrid order, view, quality and effects), written to DIR or the user's presets folder, and\n"
    "prints what was mapped, approximated, ignored or refused. A file whose shape Fractalis "
    "cannot\n"
    "draw exactly is refused (exit 1), one reason a line. --check imports every .fract file under\n"
    "DIR without writing and counts the refusals by reason.\n";

// The scene's parameter table, to check an import's values against its ranges.
struct SceneChecker {
  std::shared_ptr<const LoadedScene> scene;
  Settings settings;

  // Why the preset does not fit the scene or the settings (empty: it does).
  std::vector<std::string> problems(const Preset& preset, const ParsedOptions& options) const {
    SceneState state = make_default_state(scene->info);
    std::vector<std::string> out = apply_preset(preset, scene->info, state);
    Settings s = settings;
    try {
      apply_preset_settings(options, preset, s);
    } catch (const UsageError& e) {
      out.push_back(e.what());
    }
    return out;
  }
};

SceneChecker load_checker(const ParsedOptions& options) {
  SceneChecker c;
  c.settings = load_settings(options);
  const auto folders = plugin_folders(c.settings, options);
  if (folders.empty())
    throw std::runtime_error("no plugin folder found (build the plugins, or pass --plugins DIR)");
  c.scene = find_scene(load_plugins(folders, c.settings.plugins), kMb2SceneId);
  return c;
}

// A refusal's reason without the slot it is in ("slot 2: formula 16 ..." -> "formula 16 ...").
std::string reason_of(const std::string& refusal) {
  if (refusal.rfind("slot ", 0) == 0) {
    const size_t colon = refusal.find(": ");
    if (colon != std::string::npos) return refusal.substr(colon + 2);
  }
  return refusal;
}

int check_folder(const std::filesystem::path& dir, const ParsedOptions& options, bool list,
                 std::ostream& out) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw UsageError("--check: '" + echo(dir.string()) + "' is not a folder");
  std::vector<std::filesystem::path> files;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    std::error_code kind_ec;
    if (it->path().extension() == ".fract" && it->is_regular_file(kind_ec))
      files.push_back(it->path());
  }
  if (ec)
    throw std::runtime_error(printable(dir.string()) + ": cannot be read (" + ec.message() + ")");
  std::sort(files.begin(), files.end());
  const SceneChecker checker = load_checker(options);
  std::map<std::string, int> reasons;  // reason -> files refused for it
  int imported = 0, refused = 0, unreadable = 0;
  for (const auto& file : files) {
    std::vector<std::string> why;
    try {
      const Mb2Import result = import_fract_file(file);
      why = result.refusals();
      if (why.empty()) {
        std::vector<std::string> problems;
        const auto preset =
            preset_from_text(result.preset_toml, file, preset_id_from_file(file), &problems);
        if (preset) problems = checker.problems(*preset, options);
        for (const std::string& p : problems) why.push_back("outside the scene's ranges: " + p);
      }
    } catch (const FractError& e) {
      ++unreadable;
      out << "unreadable: " << e.what() << "\n";
      continue;
    }
    const std::string shown = printable(std::filesystem::relative(file, dir, ec).string());
    if (why.empty()) {
      ++imported;
      if (list) out << "imports: " << shown << "\n";
      continue;
    }
    ++refused;
    if (list) {
      out << "refused: " << shown << ":";
      for (const std::string& w : why) out << " " << w << ";";
      out << "\n";
    }
    std::vector<std::string> seen;
    for (const std::string& w : why) {
      const std::string r = reason_of(w);
      if (std::find(seen.begin(), seen.end(), r) == seen.end()) seen.push_back(r);
    }
    for (const std::string& r : seen) ++reasons[r];
  }
  out << files.size() << " files: " << imported << " import, " << refused << " refused, "
      << unreadable << " unreadable\n";
  std::vector<std::pair<int, std::string>> sorted;
  for (const auto& [r, n] : reasons) sorted.emplace_back(-n, r);
  std::sort(sorted.begin(), sorted.end());
  if (!sorted.empty()) out << "refusals by reason (files; a file may have several):\n";
  for (const auto& [n, r] : sorted) out << "  " << -n << "  " << r << "\n";
  return 0;
}

}  // namespace

int command_import(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> rest = args;
  std::optional<std::string> file;
  if (!rest.empty() && rest.front().rfind("--", 0) != 0) {
    file = rest.front();
    rest.erase(rest.begin());
  }
  auto specs = plugin_option_specs();
  specs.push_back(
      {"out", "DIR", false, "write the preset into DIR (default: the user's presets folder)"});
  specs.push_back(
      {"check", "DIR", false, "import every .fract file under DIR, count the refusals"});
  specs.push_back({"list", nullptr, false, "with --check: a line for each file"});
  specs.push_back({"force", nullptr, false, "replace a preset of the same name that differs"});
  specs.push_back({"help", nullptr, false, "show this help"});
  const ParsedOptions options = parse_options("import", rest, specs);
  if (options.has("help")) {
    out << kUsage << "\noptions:\n" << format_options(specs);
    return 0;
  }
  if (auto dir = options.get("check")) {
    if (file) throw UsageError("import: give FILE.fract or --check DIR, not both");
    return check_folder(*dir, options, options.has("list"), out);
  }
  if (!file) {
    err << kUsage;
    return 2;
  }
  Mb2Import result;
  try {
    result = import_fract_file(*file);
  } catch (const FractError& e) {
    throw UsageError(e.what());
  }
  for (const ImportNote& n : result.notes)
    if (n.kind != ImportNote::Kind::Refused)
      out << import_note_kind_name(n.kind) << ": " << n.item << ": " << n.text << "\n";
  std::vector<std::string> refusals = result.refusals();
  const std::string id = preset_id_from_file(*file);
  std::optional<Preset> preset;
  if (refusals.empty()) {
    std::vector<std::string> problems;
    preset = preset_from_text(result.preset_toml, *file, id, &problems);
    const SceneChecker checker = load_checker(options);
    if (preset) problems = checker.problems(*preset, options);
    for (const std::string& p : problems) refusals.push_back("outside the scene's ranges: " + p);
  }
  if (!refusals.empty()) {
    err << "fractalis import: " << printable(*file) << " cannot be imported faithfully:\n";
    for (const std::string& r : refusals) err << "refused: " << r << "\n";
    return 1;
  }
  std::filesystem::path dir;
  if (auto given = options.get("out")) {
    dir = *given;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
      throw UsageError("--out: '" + echo(*given) + "' is not a folder");
  } else {
    dir = user_scene_folder() / "presets";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot be created (" + ec.message() + ")");
  }
  const std::filesystem::path target = dir / (id + ".toml");
  {
    // A preset of that name with other contents (edited by hand, or another file's) is kept
    // unless --force says otherwise; the same import again is fine.
    std::error_code ec;
    if (std::filesystem::exists(target, ec) && !options.has("force")) {
      std::ifstream in(target, std::ios::binary);
      std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      if (old != result.preset_toml)
        throw UsageError(printable(target.string()) +
                         " exists with other contents (--force replaces it)");
    }
  }
  std::string error;
  if (!write_file_atomic(target, result.preset_toml, &error)) throw std::runtime_error(error);
  out << "wrote " << printable(target.string()) << " (preset '" << id << "' of scene '"
      << kMb2SceneId << "': fractalis render --preset " << id << ")\n";
  return 0;
}

}  // namespace fr
