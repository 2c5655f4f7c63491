// atomic_file.hpp — writing a file so that it appears whole or not at all.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace fr {

// Writes `bytes` to a temporary file beside `path`, flushes it to disk and renames it over
// `path`. On failure returns false, sets *error (naming the path and the reason) and leaves any
// existing file at `path` untouched.
bool write_file_atomic(const std::filesystem::path& path, std::string_view bytes,
                       std::string* error);

}  // namespace fr
