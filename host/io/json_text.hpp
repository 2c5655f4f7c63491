// json_text.hpp — the reports' JSON (bench --json, check --json, sweep.json) as text, through
// nlohmann-json: two-space indented, a final newline, non-finite numbers as null (JSON has no
// infinity), and text that is not valid UTF-8 (a plugin's strings, a file name) replaced, never
// an exception.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace fr {

std::string json_text(const nlohmann::ordered_json& value);

}  // namespace fr
