// echo.hpp — user input quoted back in an error message: control characters (C0 and C1) and
// invalid UTF-8 escaped by printable() (\xNN, so a message can not move the cursor or retitle the
// terminal) and anything past kEchoMaxChars cut,
// with its full length said: a 100000-character --set key does not become a 100000-character
// error line.
#pragma once

#include <string>
#include <string_view>

namespace fr {

constexpr size_t kEchoMaxChars = 80;

// "abc" -> "abc"; a long value -> "first 60 characters...last 10 (100000 bytes)".
std::string echo(std::string_view input);

}  // namespace fr
