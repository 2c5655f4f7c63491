#include "io/toml_guard.hpp"

#include <cctype>

namespace fr {

namespace {
// Deepest nesting a text may have: toml++ recurses once per level of arrays, inline tables and
// dotted key parts, so tens of thousands of levels exhaust the stack. fractalis's own files
// (settings, camera paths) are at most three levels deep.
constexpr int kMaxTomlNesting = 64;
}  // namespace

std::string toml_nesting_problem(const std::string& text, int* line_out) {
  int depth = 0, dots = 0, line = 1;
  char quote = 0;
  bool comment = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      dots = 0;
      comment = false;
      if (quote == '"' || quote == '\'') quote = 0;  // single-line strings end here anyway
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (c == '\\' && quote == '"')
        ++i;
      else if (c == quote)
        quote = 0;
      continue;
    }
    if (c == '#')
      comment = true;
    else if (c == '"' || c == '\'')
      quote = c;
    else if (c == '[' || c == '{')
      ++depth;
    else if (c == ']' || c == '}')
      depth = depth > 0 ? depth - 1 : 0;
    else if (c == '.' && !(i > 0 && std::isdigit(static_cast<unsigned char>(text[i - 1]))))
      ++dots;
    if (depth > kMaxTomlNesting || dots > kMaxTomlNesting) {
      *line_out = line;
      return "nested more than " + std::to_string(kMaxTomlNesting) +
             " levels deep (arrays, inline tables or dotted key parts); no fractalis file is "
             "more than 3 deep";
    }
  }
  return "";
}

}  // namespace fr
