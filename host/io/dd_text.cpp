#include "io/dd_text.hpp"

#include <algorithm>
#include <cmath>

namespace fr {
namespace {

using quad = __float128;

// 10^n in __float128 by squaring (n <= 400: at most nine multiplications, each within half an
// ulp, so within about 5 ulps of 2^-113).
quad power_of_ten(int n) {
  quad result = 1, base = 10;
  for (; n > 0; n >>= 1) {
    if (n & 1) result *= base;
    base *= base;
  }
  return result;
}

// The decimal digits of an integer below 2^127.
std::string integer_digits(unsigned __int128 n) {
  std::string out;
  do {
    out.push_back(static_cast<char>('0' + static_cast<int>(n % 10)));
    n /= 10;
  } while (n > 0);
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace

std::optional<DoubleDouble> parse_double_double(std::string_view text, int* significant_digits) {
  size_t at = 0;
  bool negative = false;
  if (at < text.size() && (text[at] == '+' || text[at] == '-')) negative = text[at++] == '-';
  constexpr int kKeptDigits = 36;
  quad mantissa = 0;
  int kept = 0, significant = 0, exponent = 0;
  bool any_digit = false, point = false;
  for (; at < text.size(); ++at) {
    const char c = text[at];
    if (c == '.') {
      if (point) return std::nullopt;
      point = true;
      continue;
    }
    if (c < '0' || c > '9') break;
    any_digit = true;
    const int d = c - '0';
    if (significant == 0 && d == 0) {  // a leading zero
      if (point) --exponent;
      continue;
    }
    ++significant;
    if (kept < kKeptDigits) {
      mantissa = mantissa * 10 + d;
      ++kept;
      if (point) --exponent;
    } else if (!point) {
      ++exponent;  // a dropped digit before the point still counts a place
    }
  }
  if (!any_digit) return std::nullopt;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    bool exponent_negative = false;
    if (at < text.size() && (text[at] == '+' || text[at] == '-'))
      exponent_negative = text[at++] == '-';
    if (at == text.size()) return std::nullopt;
    long long e = 0;
    for (; at < text.size(); ++at) {
      if (text[at] < '0' || text[at] > '9') return std::nullopt;
      e = std::min<long long>(e * 10 + (text[at] - '0'), 100000);
    }
    exponent += static_cast<int>(exponent_negative ? -e : e);
  }
  if (at != text.size()) return std::nullopt;
  if (significant_digits) *significant_digits = significant;
  if (significant == 0) return DoubleDouble{negative ? -0.0 : 0.0, 0.0};
  // The value's decimal exponent is exponent + kept - 1: out of a double's range, refused
  // before any arithmetic can overflow.
  const int magnitude = exponent + kept - 1;
  if (magnitude > 308 || magnitude < -290) return std::nullopt;
  quad value = exponent >= 0 ? mantissa * power_of_ten(exponent) : mantissa / power_of_ten(-exponent);
  if (negative) value = -value;
  const double hi = static_cast<double>(value);
  if (!std::isfinite(hi)) return std::nullopt;
  return DoubleDouble{hi, static_cast<double>(value - static_cast<quad>(hi))};
}

std::string format_double_double(DoubleDouble value, int digits) {
  digits = std::clamp(digits, 1, 34);
  // (Not a number parse_double_double gives, but never an undefined cast of it below.)
  if (std::isnan(value.hi) || std::isnan(value.lo)) return "nan";
  if (std::isinf(value.hi)) return value.hi < 0 ? "-inf" : "inf";
  quad v = static_cast<quad>(value.hi) + value.lo;
  std::string sign;
  if (v < 0 || (v == 0 && std::signbit(value.hi))) {
    sign = "-";
    v = -v;
  }
  if (v == 0) return sign + "0";
  // The decimal exponent, from the double's (off by one at most), then the mantissa scaled to
  // `digits` digits and rounded to an integer.
  int e10 = static_cast<int>(std::floor(std::log10(std::fabs(value.hi + value.lo))));
  auto scaled = [&](int e) {
    const int shift = digits - 1 - e;
    return shift >= 0 ? v * power_of_ten(shift) : v / power_of_ten(-shift);
  };
  quad m = scaled(e10);
  const quad low = power_of_ten(digits - 1), high = power_of_ten(digits);
  // (The value below 10^e10, tested before rounding: 0.0999...97 is not 0.1000.)
  if (m < low) m = scaled(--e10);
  else if (m >= high) m = scaled(++e10);
  // Rounded to the nearest integer, ties to even. (Not m + 0.5: near 10^34 an ulp of __float128
  // is 1, and the sum itself would round.)
  unsigned __int128 n = static_cast<unsigned __int128>(m);
  const quad fraction = m - static_cast<quad>(n);
  if (fraction > quad(0.5) || (fraction == quad(0.5) && (n & 1))) ++n;
  if (n >= static_cast<unsigned __int128>(high)) {  // rounded up to 10^digits
    n /= 10;
    ++e10;
  }
  std::string text = integer_digits(n);  // exactly `digits` digits
  while (text.size() > 1 && text.back() == '0') text.pop_back();
  if (e10 >= -4 && e10 < 21) {
    // Positional: the point after digit e10 + 1.
    if (e10 < 0) return sign + "0." + std::string(static_cast<size_t>(-e10 - 1), '0') + text;
    const size_t before = static_cast<size_t>(e10) + 1;
    if (text.size() <= before) return sign + text + std::string(before - text.size(), '0');
    return sign + text.substr(0, before) + "." + text.substr(before);
  }
  std::string out = sign + text.substr(0, 1);
  if (text.size() > 1) out += "." + text.substr(1);
  return out + "e" + std::to_string(e10);
}

}  // namespace fr
