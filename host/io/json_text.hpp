// json_text.hpp — a string as a JSON string literal (the reports write JSON by hand: a few flat
// objects, no parsing).
#pragma once

#include <string>
#include <string_view>

namespace fr {

// `s` quoted, with ", \ and control characters escaped.
std::string json_string(std::string_view s);

}  // namespace fr
