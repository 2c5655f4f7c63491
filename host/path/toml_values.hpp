// toml_values.hpp — reading scene parameter values and vectors from TOML nodes, shared by the
// camera path and preset files (so a value means the same in both, and a choice is a name in
// both). Only path/'s own sources include it: it brings toml++ with it.
#pragma once

#include "io/dd_text.hpp"
#include "scene/scene_data.hpp"

#include <toml++/toml.h>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <string>

namespace fr {

// The line a node starts on (0 when unknown).
int toml_line(const toml::node& n);
// A finite number (integers too), or nullopt.
std::optional<double> toml_number(const toml::node& n);
// [x, y, z] of finite numbers, or nullopt.
std::optional<glm::dvec3> toml_vec3(const toml::node& n);
// A position with every digit a double-double holds (deep views, docs/deep_zoom.md): [x, y, z]
// of finite numbers, or of decimal strings ("5.908838584519028311238859964040553") where a
// number needs more digits than a TOML float (a double) keeps; or nullopt.
std::optional<std::array<DoubleDouble, 3>> toml_vec3_pairs(const toml::node& n);
// A position past double as it is written back: [x, y, z] as strings of 34 digits.
std::string toml_pairs_text(const double hi[3], const double lo[3]);
// A position as it is written back: [x, y, z] of numbers (each the shortest text that reads back
// as the same double), or toml_pairs_text's strings where some lo is not zero.
std::string toml_position_text(const double hi[3], const double lo[3]);
// Parameter `p`'s value as TOML text that toml_param_value reads back as the same value: true or
// false, a whole number, a choice's name, a number or [x, y, z] (the shortest round-trip text).
std::string toml_param_text(const ParamInfo& p, const fr_value& v);
// A TOML basic string: quoted, with backslashes and quotes escaped.
std::string toml_string_text(const std::string& s);
// The value of parameter `p` in `n` (a bool, a number, [x, y, z], a choice's name), within its
// range; or nullopt with *why set ("expected a whole number", "outside the range of ...").
std::optional<fr_value> toml_param_value(const toml::node& n, const ParamInfo& p, std::string* why);

}  // namespace fr
