// kernel_sources.hpp — the files of kernels/, embedded into the host at build time.
#pragma once

#include <string_view>

namespace fr {

// The text of kernels/<name> (for example "march.cl"); throws std::out_of_range for an unknown
// name, which is a programming error.
std::string_view kernel_source(std::string_view name);

}  // namespace fr
