#include "import/fract_values.hpp"

#include "io/echo.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace fr {
namespace {

[[noreturn]] void bad(const FractFile& f, const std::string& key, const FractEntry& e,
                      const std::string& expected) {
  throw FractError(fract_where(f, e.line, key) + "expected " + expected + ", got '" +
                   echo(e.value) + "'");
}

std::vector<std::string> words(const std::string& value) {
  std::istringstream in(value);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// One number, either decimal separator; nullopt-like false when it is not one whole number.
bool parse_number(std::string w, double* out) {
  for (char& c : w)
    if (c == ',') c = '.';
  if (w.empty() || w.size() > 64) return false;
  for (char c : w)
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'))
      return false;  // no "nan", "inf", hex floats
  char* stop = nullptr;
  const double v = std::strtod(w.c_str(), &stop);
  if (*stop != '\0' || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

}  // namespace

double fract_number(const FractFile& f, const std::string& key, const FractEntry& e) {
  const auto w = words(e.value);
  double v = 0;
  if (w.size() != 1 || !parse_number(w[0], &v)) bad(f, key, e, "a finite number");
  return v;
}

long long fract_integer(const FractFile& f, const std::string& key, const FractEntry& e) {
  const auto w = words(e.value);
  double v = 0;
  if (w.size() != 1 || !parse_number(w[0], &v) || v != std::floor(v) || std::fabs(v) > 1e15)
    bad(f, key, e, "an integer");
  return static_cast<long long>(v);
}

bool fract_bool(const FractFile& f, const std::string& key, const FractEntry& e) {
  if (e.value == "true" || e.value == "1") return true;
  if (e.value == "false" || e.value == "0") return false;
  bad(f, key, e, "true or false");
}

std::array<double, 3> fract_vec3(const FractFile& f, const std::string& key, const FractEntry& e) {
  const auto w = words(e.value);
  std::array<double, 3> v{};
  if (w.size() != 3) bad(f, key, e, "three finite numbers");
  for (int i = 0; i < 3; ++i)
    if (!parse_number(w[i], &v[i])) bad(f, key, e, "three finite numbers");
  return v;
}

std::array<double, 3> fract_colour(const FractFile& f, const std::string& key,
                                   const FractEntry& e) {
  const auto w = words(e.value);
  std::array<double, 3> v{};
  if (w.size() != 3) bad(f, key, e, "a colour as three hex words (rrrr gggg bbbb)");
  for (int i = 0; i < 3; ++i) {
    if (w[i].empty() || w[i].size() > 4)
      bad(f, key, e, "a colour as three hex words of 1-4 digits");
    char* stop = nullptr;
    const long c = std::strtol(w[i].c_str(), &stop, 16);
    if (*stop != '\0' || c < 0) bad(f, key, e, "a colour as three hex words of 1-4 digits");
    v[i] = static_cast<double>(c) / 65535.0;
  }
  return v;
}

}  // namespace fr
