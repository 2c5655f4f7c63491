#include "io/printable.hpp"

#include <cstdint>
#include <cstdio>

namespace fr {
namespace {

// Length of the valid UTF-8 sequence starting at text[i], or 0 when it is not one (overlong
// forms, surrogates and code points past U+10FFFF are not valid).
size_t utf8_sequence_length(std::string_view text, size_t i) {
  const auto b = [&](size_t k) { return static_cast<uint8_t>(text[k]); };
  const uint8_t c = b(i);
  if (c < 0x80) return 1;
  size_t n = 0;
  uint32_t cp = 0, min = 0;
  if ((c & 0xE0) == 0xC0) {
    n = 2, cp = c & 0x1F, min = 0x80;
  } else if ((c & 0xF0) == 0xE0) {
    n = 3, cp = c & 0x0F, min = 0x800;
  } else if ((c & 0xF8) == 0xF0) {
    n = 4, cp = c & 0x07, min = 0x10000;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((b(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b(i + k) & 0x3F);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

bool is_control(uint32_t c) {
  return c < 0x20 || c == 0x7F;
}

}  // namespace

std::string utf8_text_problem(std::string_view text, bool multiline) {
  for (size_t i = 0; i < text.size();) {
    const size_t n = utf8_sequence_length(text, i);
    if (n == 0) return "invalid UTF-8 at byte " + std::to_string(i);
    const auto c = static_cast<uint8_t>(text[i]);
    // C1 controls (U+0080..U+009F) are two bytes, C2 80..C2 9F; some terminals obey them.
    const bool c1 = n == 2 && c == 0xC2 && static_cast<uint8_t>(text[i + 1]) < 0xA0;
    if ((n == 1 && is_control(c) && !(multiline && (c == '\n' || c == '\t' || c == '\r'))) || c1) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c1 ? static_cast<uint8_t>(text[i + 1]) : c);
      return std::string("control character ") + hex + " at byte " + std::to_string(i);
    }
    i += n;
  }
  return "";
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const size_t n = utf8_sequence_length(text, i);
    const auto c = static_cast<uint8_t>(text[i]);
    const bool c1 = n == 2 && c == 0xC2 && static_cast<uint8_t>(text[i + 1]) < 0xA0;
    if (n == 0 || (n == 1 && is_control(c)) || c1) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
      i += 1;
      continue;
    }
    out.append(text.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace fr
