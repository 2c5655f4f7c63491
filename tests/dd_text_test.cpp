// Numbers as text to and from double-double (io/dd_text.hpp), against values computed apart in
// exact rational arithmetic (Python's fractions and decimal, the results written here as
// hexadecimal doubles): the nearest pair to a decimal, its 34-digit text, what is refused, and
// that any pair printed with 34 digits reads back as the same pair.
#include "io/dd_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace fr {
namespace {

void expect_pair(const char* text, double hi, double lo) {
  const auto got = parse_double_double(text);
  ASSERT_TRUE(got) << text;
  EXPECT_EQ(got->hi, hi) << text;
  EXPECT_EQ(got->lo, lo) << text;
}

// hi the nearest double to the decimal, lo the nearest double to the rest (exact arithmetic).
TEST(DdText, ParsesToTheNearestPair) {
  expect_pair("0.1", 0x1.999999999999ap-4, -0x1.999999999999ap-58);
  expect_pair("1e-20", 0x1.79ca10c924223p-67, 0x1.75447a5d8e536p-121);
  expect_pair("-1.2345678901234567890123456789012345e-3", -0x1.43a272d9e0e51p-10,
              -0x1.67092f77a8d03p-64);
  // 62 digits of pi: kept to what a pair holds (the digits past the 36th dropped), said by the
  // count.
  int digits = 0;
  const auto pi = parse_double_double(
      "3.14159265358979323846264338327950288419716939937510582097494459", &digits);
  ASSERT_TRUE(pi);
  EXPECT_EQ(digits, 63);
  EXPECT_EQ(pi->hi, 0x1.921fb54442d18p+1);
  EXPECT_EQ(pi->lo, 0x1.1a62633145c07p-53);
  // Leading zeros, a point without digits before it, an exponent's sign and case.
  expect_pair("000.100", 0x1.999999999999ap-4, -0x1.999999999999ap-58);
  expect_pair(".1e0", 0x1.999999999999ap-4, -0x1.999999999999ap-58);
  expect_pair("100E-3", 0x1.999999999999ap-4, -0x1.999999999999ap-58);
  expect_pair("+2", 2.0, 0.0);
  expect_pair("-0", -0.0, 0.0);
}

TEST(DdText, PrintsThirtyFourDigits) {
  // The pair nearest 0.1 is 0.0999...99969 (to 34 digits), not 0.1.
  EXPECT_EQ(format_double_double({0x1.999999999999ap-4, -0x1.999999999999ap-58}),
            "0.09999999999999999999999999999999969");
  EXPECT_EQ(format_double_double({0x1.999999999999ap-4, -0x1.999999999999ap-58}, 17), "0.1");
  EXPECT_EQ(format_double_double({2.0, 0.0}), "2");
  EXPECT_EQ(format_double_double({-1500.0, 0.0}), "-1500");
  EXPECT_EQ(format_double_double({0.0, 0.0}), "0");
  EXPECT_EQ(format_double_double({0x1.79ca10c924223p-67, 0x1.75447a5d8e536p-121}, 20), "1e-20");
  EXPECT_EQ(format_double_double({1e25, 0.0}, 5), "1e25");
  EXPECT_EQ(format_double_double({-INFINITY, 0.0}), "-inf");
  EXPECT_EQ(format_double_double({NAN, 0.0}), "nan");
  EXPECT_FALSE(parse_double_double(format_double_double({INFINITY, 0.0})));
}

TEST(DdText, RefusesWhatIsNotANumberOrDoesNotFit) {
  for (const char* bad : {"", "-", ".", "1.2.3", "nan", "inf", "0x10", " 1", "1 ", "1e", "1e+",
                          "1e-", "e5", "1,5", "1e400", "-2e308", "1e-300"})
    EXPECT_FALSE(parse_double_double(bad)) << "'" << bad << "'";
}

// Any normalised pair (|lo| at most half an ulp of hi), printed with 34 digits, reads back as the
// same value to the pair's precision: hi exactly, lo within 2^-104 |hi| (34 digits resolve about
// 1e-34 of the value; a pair holds 2^-106, about 1.2e-32). A pair whose lo is far below hi's last
// bit spells more bits than any 34 digits, so lo bit for bit is not asked.
TEST(DdText, ThirtyFourDigitsReadBackAsThePair) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-250, 250);
  for (int i = 0; i < 20000; ++i) {
    const double hi = std::ldexp(unit(random), exponent(random));
    if (hi == 0) continue;
    const double half_ulp = std::fabs(std::nextafter(hi, 2 * hi) - hi) / 2;
    double lo = unit(random) * half_ulp;
    // (hi + lo must round to hi: keep |lo| strictly inside half an ulp.)
    if (hi + lo != hi) lo /= 2;
    const DoubleDouble pair{hi, lo};
    const std::string text = format_double_double(pair);
    const auto back = parse_double_double(text);
    ASSERT_TRUE(back) << text;
    ASSERT_EQ(back->hi, pair.hi) << text;
    ASSERT_LE(std::fabs(back->lo - pair.lo), std::ldexp(std::fabs(hi), -104))
        << text << " read back as " << back->hi << " + " << back->lo;
  }
}

}  // namespace
}  // namespace fr
