// printable.hpp — checking text that comes from outside (a plugin, a file, the command line),
// and printing it safely. The one escaper: echo.hpp quotes user input through it too.
//
// A plugin's strings reach terminals, logs, the overlay and file names. Escape sequences in them
// could rewrite what the user sees, and invalid UTF-8 breaks every consumer, so the loader refuses
// such strings (utf8_text_problem) and everything the host prints about a file, a plugin's log or
// the user's own input goes through printable().
#pragma once

#include <string>
#include <string_view>

namespace fr {

// Why `text` is not clean UTF-8 text ("invalid UTF-8 at byte 5", "control character 0x1b at byte
// 0"), or "" when it is. `multiline` allows newline, tab and carriage return (source code).
std::string utf8_text_problem(std::string_view text, bool multiline);

// `text` with every control character and every byte that is not part of valid UTF-8 written as
// \xNN, so printing it cannot move the cursor, change colours or break the output's encoding.
std::string printable(std::string_view text);

}  // namespace fr
