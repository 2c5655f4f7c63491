#include "settings/settings.hpp"

#include "io/echo.hpp"
#include "io/toml_guard.hpp"
#include "platform/user_folders.hpp"
#include "settings/key_bindings.hpp"
#include "settings/settings_table.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fr {
namespace {

const char* const kDefaultFileHeader =
    "Fractalis settings — the built-in defaults, written out.\n"
    "\n"
    "Copy this file to $XDG_CONFIG_HOME/fractalis/config.toml (usually ~/.config/fractalis/) "
    "and\n"
    "change what you need, or pass one with `--config FILE`; `--set KEY=VALUE` overrides a "
    "single\n"
    "key on the command line (for example --set render.effects.fog=false). Every key is checked: "
    "a\n"
    "typo is reported with its file, line and the nearest known key, and a wrong value names "
    "what\n"
    "was expected. Generated from host/settings/settings_table.cpp; tests/settings_test.cpp "
    "checks\n"
    "that this file is what the table writes.";

// The comment above [controls.keys], with the action names and default keys from their tables
// (settings/key_bindings.hpp).
std::string key_bindings_comment() {
  std::string text =
      "Extra key bindings over the defaults, action = \"key name\" (SDL's names: \"W\", \"Left "
      "Shift\", \"Up\", \"F5\", ...). Actions and their default keys:";
  const KeyBindings defaults = KeyBindings::defaults();
  for (const auto& row : kActionNames)
    text += std::string(" ") + row.name + " (" + defaults.label(row.value) + "),";
  text.back() = '.';
  // Wrapped to 96 columns.
  std::string wrapped, line;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (!line.empty() && line.size() + 1 + word.size() > 96) wrapped += line + "\n", line.clear();
    line += (line.empty() ? "" : " ") + word;
  }
  return wrapped + line;
}

// The node's value as a setting takes it; monostate for types no setting takes.
SettingValue node_value(const toml::node& n) {
  if (auto v = n.value_exact<bool>()) return *v;
  if (auto v = n.value_exact<int64_t>()) return static_cast<long long>(*v);
  if (auto v = n.value_exact<double>()) return *v;
  if (auto v = n.value_exact<std::string>()) return *v;
  if (const auto* arr = n.as_array()) {
    // Three numbers: a colour. (An empty array stays a list of strings.)
    if (arr->size() == 3 && std::all_of(arr->begin(), arr->end(), [](const toml::node& item) {
          return item.is_number();
        })) {
      SettingColor c{};
      for (size_t i = 0; i < 3; ++i) c[i] = *(*arr)[i].value<double>();
      return c;
    }
    std::vector<std::string> items;
    for (const auto& item : *arr) {
      if (!item.is_string()) return std::monostate{};
      items.push_back(item.as_string()->get());
    }
    return items;
  }
  return std::monostate{};
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

void apply_key_bindings(const toml::node& node, const std::string& file, Settings& s,
                        std::vector<SettingsProblem>& problems) {
  const auto* table = node.as_table();
  if (!table) {
    problems.push_back({file, static_cast<int>(node.source().begin.line), "controls.keys",
                        "expected a table of action = \"key name\""});
    return;
  }
  for (const auto& [action, value] : *table) {
    const std::string key = "controls.keys." + std::string(action.str());
    const int line = static_cast<int>(value.source().begin.line);
    if (!action_from_name(std::string(action.str()))) {
      problems.push_back(
          {file, line, key, "unknown action (expected one of " + enum_name_list<Action>() + ")"});
    } else if (!value.is_string() || value.as_string()->get().empty()) {
      problems.push_back({file, line, key, "expected a key name such as \"W\" or \"Left Shift\""});
    } else {
      s.explorer.key_bindings[value.as_string()->get()] = std::string(action.str());
    }
  }
}

bool is_key_prefix(const std::string& prefix) {
  if (prefix == "controls") return true;
  return std::any_of(settings_table().begin(), settings_table().end(), [&](const SettingSpec& k) {
    return std::string(k.key).rfind(prefix + ".", 0) == 0;
  });
}

// Applies every leaf of `table`, reporting unknown keys and bad values.
void apply_table(const toml::table& table, const std::string& prefix, const std::string& file,
                 Settings& s, std::vector<SettingsProblem>& problems) {
  for (const auto& [k, node] : table) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    const int line = static_cast<int>(node.source().begin.line);
    if (key == "controls.keys") {
      apply_key_bindings(node, file, s, problems);
      continue;
    }
    if (const auto* sub = node.as_table(); sub && is_key_prefix(key)) {
      apply_table(*sub, key, file, s, problems);
      continue;
    }
    const SettingSpec* spec = find_setting(key);
    if (!spec) {
      const std::string nearest = nearest_known_key(key);
      problems.push_back(
          {file, line, key,
           nearest.empty() ? "unknown key" : "unknown key (did you mean '" + nearest + "'?)"});
      continue;
    }
    const SettingValue value = node_value(node);
    if (std::string error = check_setting(*spec, value); !error.empty())
      problems.push_back({file, line, key, error});
    else
      spec->set(s, value);
  }
}

std::vector<SettingsProblem> apply_toml(const std::string& text, const std::string& file,
                                        Settings& s) {
  std::vector<SettingsProblem> problems;
  int deep_line = 0;
  if (std::string why = toml_nesting_problem(text, &deep_line); !why.empty()) {
    problems.push_back({file, deep_line, "", why});
    return problems;
  }
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    problems.push_back({file, static_cast<int>(e.source().begin.line), "",
                        "not valid TOML: " + std::string(e.description())});
    return problems;
  }
  apply_table(root, "", file, s, problems);
  std::stable_sort(
      problems.begin(), problems.end(),
      [](const SettingsProblem& a, const SettingsProblem& b) { return a.line < b.line; });
  return problems;
}

}  // namespace

std::string SettingsProblem::to_string() const {
  return file + (line > 0 ? ":" + std::to_string(line) : "") + ": " +
         (key.empty() ? "" : "key '" + echo(key) + "': ") + message;
}

std::string nearest_known_key(const std::string& key) {
  if (key.size() > 200) return "";  // no key is near one this long
  std::string best;
  size_t best_d = ~size_t{0};
  for (const SettingSpec& known : settings_table()) {
    size_t d = edit_distance(key, known.key);
    if (d < best_d) best_d = d, best = known.key;
  }
  return best;
}

std::string format_settings_toml(const Settings& s, const std::string& header) {
  std::ostringstream out;
  auto comment = [&](const char* text) {
    std::istringstream lines(text ? text : "");
    for (std::string line; std::getline(lines, line);)
      out << (line.empty() ? "#" : "# " + line) << "\n";
  };
  comment(header.c_str());
  for (const SettingsSection& section : settings_sections()) {
    out << "\n";
    comment(section.comment);
    out << "[" << section.table << "]\n";
    for (const SettingSpec& spec : settings_table()) {
      const std::string key = spec.key;
      if (key.substr(0, key.rfind('.')) != section.table) continue;
      comment(spec.comment);
      out << key.substr(key.rfind('.') + 1) << " = " << setting_value_toml(spec, spec.get(s))
          << "\n";
    }
  }
  out << "\n";
  comment(key_bindings_comment().c_str());
  out << "[controls.keys]\n";
  for (const auto& [key, action] : s.explorer.key_bindings)
    out << action << " = " << toml_basic_string(key) << "\n";
  return out.str();
}

std::string default_settings_toml() {
  return format_settings_toml(Settings{}, kDefaultFileHeader);
}

std::vector<std::string> known_setting_keys() {
  std::vector<std::string> names;
  for (const SettingSpec& k : settings_table()) names.emplace_back(k.key);
  return names;
}

std::filesystem::path user_settings_path() {
  const std::filesystem::path folder = user_folder(UserFolder::Config);
  return folder.empty() ? folder : folder / "config.toml";
}

std::optional<std::filesystem::path> user_settings_file() {
  const auto file = user_settings_path();
  if (file.empty()) return std::nullopt;
  std::error_code ec;
  if (std::filesystem::is_regular_file(file, ec)) return file;
  return std::nullopt;
}

std::vector<SettingsProblem> load_settings_file(const std::filesystem::path& file, Settings& s) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {{file.string(), 0, "", "cannot read the file"}};
  std::stringstream text;
  text << in.rdbuf();
  return apply_toml(text.str(), file.string(), s);
}

std::vector<SettingsProblem> load_settings_text(const std::string& text, const std::string& name,
                                                Settings& s) {
  return apply_toml(text, name, s);
}

std::vector<SettingsProblem> apply_setting_override(const std::string& assignment, Settings& s) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos)
    return {{"--set", 0, "", "expected KEY=VALUE, got '" + echo(assignment) + "'"}};
  std::string key = assignment.substr(0, eq), value = assignment.substr(eq + 1);
  // Bare words are strings ("--set render.shading_model=lambert"); numbers, booleans, quoted
  // strings and arrays pass as TOML.
  const bool bare_word = !value.empty() && value.find_first_of("\"[{") == std::string::npos &&
                         value != "true" && value != "false" &&
                         value.find_first_not_of("+-.0123456789eE_") != std::string::npos;
  if (bare_word) value = "\"" + value + "\"";
  auto problems = apply_toml(key + " = " + value + "\n", "--set " + echo(assignment), s);
  for (auto& p : problems) p.line = 0;
  return problems;
}

}  // namespace fr
