// toml_guard.hpp — what must be checked before handing a text to toml++.
#pragma once

#include <string>

namespace fr {

// Why `text` nests too deeply to parse safely, with *line_out set to where, or "". toml++
// recurses per level of arrays, inline tables and dotted key parts; tens of thousands of levels
// exhaust the stack (a crash, not an error). Brackets, braces and dots inside strings and
// comments do not count.
std::string toml_nesting_problem(const std::string& text, int* line_out);

}  // namespace fr
