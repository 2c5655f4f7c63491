// enum_names.hpp — the names of an enum's values, kept beside the enum as a table of EnumName
// rows and found through an `enum_names(Enum)` overload declared with it (render_settings.hpp,
// plugin_policy.hpp). Settings files, --set, CLI options, the overlay and the kernel assembler
// all read the names from there, so no list of names is kept anywhere else.
#pragma once

#include "io/check.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace fr {

// One row per value of an enum that a setting picks from: the name in
// settings files and on the command line, the overlay's label, and (for the kernel's switches)
// the macro the kernel tests, `#if FR_SHADING == FR_SHADING_LAMBERT`, whose number the kernel
// assembler makes up from the row's place in this table, not from the enum's value.
template <typename Enum>
struct EnumName {
  Enum value;
  const char* name;           // settings files, --set and CLI options
  const char* label;          // the overlay
  const char* kernel_define;  // null for enums the kernel never sees
};

// The row of `value` in its enum's table (every value is listed: a missing row is a bug).
template <typename Enum>
constexpr const EnumName<Enum>& enum_row(Enum value) {
  for (const auto& row : enum_names(value))
    if (row.value == value) return row;
  FR_CHECK(false, "an enum value has no row in its table of names");
  return enum_names(value).front();  // not reached
}
template <typename Enum>
constexpr const char* enum_name(Enum value) {
  return enum_row(value).name;
}
// The value named `name`, or nullopt.
template <typename Enum>
std::optional<Enum> enum_from_name(std::string_view name) {
  for (const auto& row : enum_names(Enum{}))
    if (name == row.name) return row.value;
  return std::nullopt;
}
// "a, b or c", for messages.
template <typename Enum>
std::string enum_name_list() {
  std::string out;
  const auto rows = enum_names(Enum{});
  for (size_t i = 0; i < rows.size(); ++i)
    out += (i == 0 ? "" : i + 1 == rows.size() ? " or " : ", ") + std::string(rows[i].name);
  return out;
}
}  // namespace fr
