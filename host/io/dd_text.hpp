// dd_text.hpp — numbers as text to and from double-double precision, for deep views.
//
// A camera 1e-20 from a surface needs its eye to about 32 digits, more than a double's 17: such
// a number is a pair hi + lo of doubles (kernels/de/dd.cl), and its text is what the user typed
// or a file keeps. Parsing and printing go through __float128 (113 bits, 34 digits), more than
// the pair's 106 bits, so a pair printed with 34 digits reads back as the same value to the
// pair's own precision: hi exactly, lo within 2^-104 of |hi|. (Not always lo bit for bit: a pair
// whose lo is far below hi's last bit spells more than 113 bits, which no 34 digits hold.)
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fr {

// Significant digits a pair's text carries (format_double_double's most; a pair holds about 32).
constexpr int kPairDigits = 34;

struct DoubleDouble {
  double hi = 0;  // the nearest double
  double lo = 0;  // the rest, rounded to a double: |lo| <= ulp(hi) / 2
  bool operator==(const DoubleDouble&) const = default;
};

// a + b as a normalised pair (Knuth's TwoSum for a.hi + b, then a.lo, then the quick TwoSum):
// how the host moves a position in pairs (the camera, a path's zoom, check's march). Not for a
// compiler that reassociates floating point (the project builds without -ffast-math).
inline DoubleDouble pair_plus(DoubleDouble a, double b) {
  const double s = a.hi + b, bb = s - a.hi;
  const double e = (a.hi - (s - bb)) + (b - bb) + a.lo;
  const double hi = s + e;
  return {hi, e - (hi - s)};
}

// A decimal number: an optional sign, digits with an optional point, an optional exponent
// ("-1.25", "3e-21", ".5E+3"). Digits past the 36th significant one are dropped (a pair holds
// about 32); *significant_digits, when given, receives how many the text had. Nullopt for
// anything else (empty, "1.2.3", "nan", "inf", "0x10", spaces) and for a value a double cannot
// hold (above about 1.8e308, or a nonzero value below 1e-290, where lo would be subnormal).
std::optional<DoubleDouble> parse_double_double(std::string_view text,
                                                int* significant_digits = nullptr);

// The pair's value with `digits` significant digits (1 to 34), in exponent form when it is
// below 1e-4 or at least 1e21, as "-1.2345e-21"; trailing zeros of the mantissa dropped. A pair
// that is not finite prints as "nan", "inf" or "-inf" (and does not parse back).
std::string format_double_double(DoubleDouble value, int digits = 34);

}  // namespace fr
