#include "io/echo.hpp"

#include "io/printable.hpp"

namespace fr {

std::string echo(std::string_view input) {
  if (input.size() <= kEchoMaxChars) return printable(input);
  // Head and tail, cut on bytes that do not split a UTF-8 sequence.
  size_t head = 60, tail = 10;
  while (head > 0 && (static_cast<unsigned char>(input[head]) & 0xC0) == 0x80) --head;
  size_t tail_start = input.size() - tail;
  while (tail_start < input.size() &&
         (static_cast<unsigned char>(input[tail_start]) & 0xC0) == 0x80)
    ++tail_start;
  return printable(input.substr(0, head)) + "..." + printable(input.substr(tail_start)) + " (" +
         std::to_string(input.size()) + " bytes)";
}

}  // namespace fr
