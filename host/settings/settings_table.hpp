// settings_table.hpp — every settings key, once: its type, the values it accepts, the comment
// written above it, how to read and write it in a Settings, and (for some) the overlay widget.
// Reading files and --set, writing the user's file, config/default.toml (generated from this
// table; tests/settings_test.cpp checks the file is the table's output) and the overlay's
// rendering panel all walk this table, so a key added here is known to all of them.
#pragma once

#include "settings/settings.hpp"

#include <array>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace fr {

enum class SettingKind {
  Bool,
  Int,      // long long in a SettingValue
  Number,   // double in a SettingValue
  Choice,   // one of `choices`, by name (a std::string in a SettingValue)
  Text,     // std::string
  TextList,  // std::vector<std::string>
  Color      // three numbers, each in [min, max] (a SettingColor in a SettingValue)
};

// monostate: a value of no type a setting takes (a date, a table, an array of other than three
// numbers).
using SettingColor = std::array<double, 3>;
using SettingValue = std::variant<std::monostate, bool, long long, double, std::string,
                                  std::vector<std::string>, SettingColor>;

struct SettingChoice {
  const char* name;   // in files and on the command line
  const char* label;  // in the overlay
};

struct SettingSpec {
  const char* key;  // "render.max_steps": the TOML table path and the key
  SettingKind kind;
  const char* comment;      // the lines above the key in written files, without "# "; '\n' splits
  double min = 0, max = 0;  // Int and Number: the accepted range
  bool min_open = false;    // Number: the range excludes min
  bool single_precision = false;       // Number: stored as float (written with float's digits)
  std::vector<long long> only_ints;    // Int: when not empty, the only values accepted
  const char* only_ints_text = "";     // Int: how a message describes only_ints
  std::vector<SettingChoice> choices;  // Choice

  // A check beyond the kind's (a file that must be readable): what is wrong with a value of the
  // right kind, or "". Null: none.
  std::string (*check)(const SettingValue&) = nullptr;

  SettingValue (*get)(const Settings&) = nullptr;
  void (*set)(Settings&, const SettingValue&) = nullptr;  // with a value check_setting accepted

  // The overlay's widget, when `label` is set: a slider over [ui_min, ui_max] (logarithmic when
  // ui_log) for numbers, a checkbox for booleans, a combo box for choices.
  const char* label = nullptr;
  double ui_min = 0, ui_max = 0;
  bool ui_log = false;
};

// Every key, in the order written files list them (grouped by table).
std::span<const SettingSpec> settings_table();
const SettingSpec* find_setting(const std::string& key);

// What is wrong with `value` for `spec` ("expected an integer in [1, 4096]"), or "".
std::string check_setting(const SettingSpec& spec, const SettingValue& value);

// The TOML text of a value (strings quoted and escaped, floats with a decimal point).
std::string setting_value_toml(const SettingSpec& spec, const SettingValue& value);

std::string toml_basic_string(const std::string& text);  // "text", escaped

// The tables written files have, in order, and the comment above each table's header ("" for
// none); a key belongs to the table its key names up to the last dot.
struct SettingsSection {
  const char* table;
  const char* comment;
};
std::span<const SettingsSection> settings_sections();

}  // namespace fr
