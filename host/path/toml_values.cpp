#include "path/toml_values.hpp"

#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <sstream>

namespace fr {
namespace {

std::string range_text(const ParamInfo& p) {
  std::ostringstream out;
  out << "[" << p.min_value.v[0] << ", " << p.max_value.v[0] << "]";
  return out.str();
}

}  // namespace

int toml_line(const toml::node& n) {
  return static_cast<int>(n.source().begin.line);
}

// A finite number (integers too), or nullopt.
std::optional<double> toml_number(const toml::node& n) {
  if (!n.is_number()) return std::nullopt;
  const double v = *n.value<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

std::optional<glm::dvec3> toml_vec3(const toml::node& n) {
  const auto* a = n.as_array();
  if (!a || a->size() != 3) return std::nullopt;
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) {
    auto c = toml_number(*a->get(static_cast<size_t>(i)));
    if (!c) return std::nullopt;
    v[i] = *c;
  }
  return v;
}

std::optional<std::array<DoubleDouble, 3>> toml_vec3_pairs(const toml::node& n) {
  const auto* a = n.as_array();
  if (!a || a->size() != 3) return std::nullopt;
  std::array<DoubleDouble, 3> v;
  for (int i = 0; i < 3; ++i) {
    const toml::node& c = *a->get(static_cast<size_t>(i));
    if (const auto text = c.value<std::string>()) {
      const auto pair = parse_double_double(*text);
      if (!pair) return std::nullopt;
      v[i] = *pair;
    } else if (const auto number = toml_number(c)) {
      v[i] = DoubleDouble{*number, 0};
    } else {
      return std::nullopt;
    }
  }
  return v;
}

std::string toml_pairs_text(const double hi[3], const double lo[3]) {
  std::string out = "[";
  for (int i = 0; i < 3; ++i)
    out += (i > 0 ? ", \"" : "\"") + format_double_double(DoubleDouble{hi[i], lo[i]}) + '"';
  return out + "]";
}

std::string toml_position_text(const double hi[3], const double lo[3]) {
  if (lo[0] != 0 || lo[1] != 0 || lo[2] != 0) return toml_pairs_text(hi, lo);
  return fmt::format("[{}, {}, {}]", hi[0], hi[1], hi[2]);
}

std::string toml_param_text(const ParamInfo& p, const fr_value& v) {
  switch (p.type) {
    case FR_PARAM_BOOL:
      return v.v[0] != 0 ? "true" : "false";
    case FR_PARAM_INT:
      return fmt::format("{}", static_cast<long long>(v.v[0]));
    case FR_PARAM_CHOICE:
      return toml_string_text(p.choice_name(v));
    case FR_PARAM_FLOAT:
      return fmt::format("{}", v.v[0]);
    default:
      return fmt::format("[{}, {}, {}]", v.v[0], v.v[1], v.v[2]);
  }
}

std::string toml_string_text(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

// The value of parameter `p` in `n`, or why not.
std::optional<fr_value> toml_param_value(const toml::node& n, const ParamInfo& p, std::string* why) {
  fr_value v{};
  switch (p.type) {
    case FR_PARAM_BOOL:
      if (!n.is_boolean()) {
        *why = "expected true or false";
        return std::nullopt;
      }
      v.v[0] = *n.value<bool>() ? 1 : 0;
      return v;
    case FR_PARAM_CHOICE: {
      // A name, never an index (as on the command line).
      const auto name = n.value<std::string>();
      const int index = name ? p.choice_index(*name) : -1;
      if (index < 0) {
        std::string names;
        for (const std::string& c : p.choices) {
          if (!names.empty()) names += ", ";
          names += c;
        }
        *why = "expected one of the names " + names;
        return std::nullopt;
      }
      v.v[0] = index;
      return v;
    }
    case FR_PARAM_INT: {
      auto x = toml_number(n);
      if (!x || *x != std::floor(*x)) {
        *why = "expected a whole number";
        return std::nullopt;
      }
      v.v[0] = *x;
      break;
    }
    case FR_PARAM_FLOAT: {
      auto x = toml_number(n);
      if (!x) {
        *why = "expected a finite number";
        return std::nullopt;
      }
      v.v[0] = *x;
      break;
    }
    default: {
      auto x = toml_vec3(n);
      if (!x) {
        *why = "expected [x, y, z] (three finite numbers)";
        return std::nullopt;
      }
      for (int i = 0; i < 3; ++i) v.v[i] = (*x)[i];
    }
  }
  for (int i = 0; i < p.component_count(); ++i)
    if (!(v.v[i] >= p.min_value.v[i] && v.v[i] <= p.max_value.v[i])) {
      *why = "outside the range of '" + p.key + "' " + range_text(p);
      return std::nullopt;
    }
  return v;
}

}  // namespace fr
