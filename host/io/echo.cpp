#include "io/echo.hpp"

#include <cstdio>

namespace fr {
namespace {

std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string echo(std::string_view input) {
  if (input.size() <= kEchoMaxChars) return escaped(input);
  // Head and tail, cut on bytes that do not split a UTF-8 sequence.
  size_t head = 60, tail = 10;
  while (head > 0 && (static_cast<unsigned char>(input[head]) & 0xC0) == 0x80) --head;
  size_t tail_start = input.size() - tail;
  while (tail_start < input.size() &&
         (static_cast<unsigned char>(input[tail_start]) & 0xC0) == 0x80)
    ++tail_start;
  return escaped(input.substr(0, head)) + "..." + escaped(input.substr(tail_start)) + " (" +
         std::to_string(input.size()) + " bytes)";
}

}  // namespace fr
