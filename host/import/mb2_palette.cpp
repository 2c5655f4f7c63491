#include "import/mb2_palette.hpp"

#include "io/echo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fr {
namespace {

[[noreturn]] void bad(const FractFile& f, const std::string& key, const FractEntry& e,
                      const std::string& what) {
  throw FractError(fract_where(f, e.line, key) + what + " in '" + echo(e.value.substr(0, 80)) +
                   (e.value.size() > 80 ? "...'" : "'"));
}

// Mandelbulber2 splits at single spaces (an empty token between two spaces is kept and skipped).
std::vector<std::string> split_spaces(const std::string& s) {
  std::vector<std::string> out(1);
  for (char c : s) {
    if (c == ' ')
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

// RRGGBB; Mandelbulber2 writes it without leading zeros ("f0c05" is 0f0c05).
bool parse_hex_colour(const std::string& w, std::array<int, 3>* rgb) {
  if (w.empty() || w.size() > 6) return false;
  char* stop = nullptr;
  const long v = std::strtol(w.c_str(), &stop, 16);
  if (*stop != '\0' || v < 0) return false;
  *rgb = {static_cast<int>(v >> 16), static_cast<int>((v >> 8) & 255), static_cast<int>(v & 255)};
  return true;
}

// The first colour again at position 1, then sorted by position (stable: ties keep file order).
Mb2Gradient finish(std::vector<Mb2GradientStop> stops) {
  Mb2Gradient g;
  g.colours = static_cast<int>(stops.size());
  Mb2GradientStop wrap = stops.front();
  wrap.position = 1.0f;
  stops.push_back(wrap);
  std::stable_sort(
      stops.begin(), stops.end(),
      [](const Mb2GradientStop& a, const Mb2GradientStop& b) { return a.position < b.position; });
  g.stops = std::move(stops);
  return g;
}

}  // namespace

Mb2Gradient mb2_parse_gradient(const FractFile& f, const std::string& key, const FractEntry& e) {
  const auto tokens = split_spaces(e.value);
  std::vector<Mb2GradientStop> stops;
  float position = 0;
  int index = 0;  // of the non-empty tokens: positions at even, colours at odd
  for (const std::string& t : tokens) {
    if (t.empty()) continue;
    if (index % 2 == 0) {
      char* stop = nullptr;
      const long p = std::strtol(t.c_str(), &stop, 10);
      if (*stop != '\0' || t.size() > 6 || p < 0 || p > 10000)
        bad(f, key, e, "expected a position 0-10000, got '" + echo(t) + "'");
      position = static_cast<float>(p) / 10000.0f;
    } else {
      Mb2GradientStop s;
      s.position = position;
      if (!parse_hex_colour(t, &s.rgb))
        bad(f, key, e, "expected a colour RRGGBB, got '" + echo(t) + "'");
      stops.push_back(s);
    }
    ++index;
  }
  if (stops.empty() || index % 2 != 0) bad(f, key, e, "expected position and colour pairs");
  return finish(std::move(stops));
}

Mb2Gradient mb2_parse_old_palette(const FractFile& f, const std::string& key, const FractEntry& e) {
  auto tokens = split_spaces(e.value);
  // Mandelbulber2 drops a last token shorter than six digits (meant for a trailing space, it
  // drops a colour written without its leading zeros too).
  if (!tokens.empty() && tokens.back().size() < 6) tokens.pop_back();
  if (tokens.empty()) bad(f, key, e, "expected at least one colour");
  const double step = 1.0 / static_cast<double>(tokens.size());
  std::vector<Mb2GradientStop> stops;
  for (size_t i = 0; i < tokens.size(); ++i) {
    Mb2GradientStop s;
    s.position =
        static_cast<float>(static_cast<int>(static_cast<double>(i) * step * 10000.0)) / 10000.0f;
    if (!parse_hex_colour(tokens[i], &s.rgb))
      bad(f, key, e, "expected a colour RRGGBB, got '" + echo(tokens[i]) + "'");
    stops.push_back(s);
  }
  return finish(std::move(stops));
}

std::array<double, 3> mb2_gradient_colour(const Mb2Gradient& g, float position) {
  const auto& s = g.stops;  // at least two: a colour and its wrap
  size_t i = 0;
  while (i + 1 < s.size() && position > s[i + 1].position) ++i;
  std::array<double, 3> out{};
  if (i + 1 == s.size()) {
    // Past the last stop Mandelbulber2 takes the one before it.
    for (int c = 0; c < 3; ++c) out[c] = s[i - 1].rgb[c] / 255.0;
    return out;
  }
  const float p1 = s[i].position, p2 = s[i + 1].position;
  if (!(p2 - p1 > 0.0f)) {
    for (int c = 0; c < 3; ++c) out[c] = s[i].rgb[c] / 255.0;
    return out;
  }
  const float t = (position - p1) / (p2 - p1);
  for (int c = 0; c < 3; ++c)
    out[c] = std::clamp((s[i].rgb[c] * (1.0f - t) + s[i + 1].rgb[c] * t) / 255.0f, 0.0f, 1.0f);
  return out;
}

double srgb_to_linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace fr
