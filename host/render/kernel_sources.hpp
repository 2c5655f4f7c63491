// kernel_sources.hpp — the files of kernels/, embedded into the host at build time.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fr {

// The text of kernels/<name> (for example "march.cl" or "de/folds.cl"); throws std::out_of_range
// for an unknown name, which is a programming error.
std::string_view kernel_source(std::string_view name);

// The DE helper library as scenes include it: "fr/primitives.cl", ... (kernels/de/ on disk).
std::vector<std::string> kernel_library_files();

}  // namespace fr
