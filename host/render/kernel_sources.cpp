#include "render/kernel_sources.hpp"

#include <stdexcept>
#include <string>

// The generated embedded_kernels.c (host/CMakeLists.txt lists the files).
extern "C" {
struct fr_embedded_file {
  const char* name;
  const char* text;
};
extern const fr_embedded_file fr_embedded_kernels[];
extern const int fr_embedded_kernels_count;
}

namespace fr {

std::string_view kernel_source(std::string_view name) {
  for (int i = 0; i < fr_embedded_kernels_count; ++i)
    if (fr_embedded_kernels[i].name == name) return fr_embedded_kernels[i].text;
  throw std::out_of_range("no embedded kernel file named " + std::string(name));
}

std::vector<std::string> kernel_library_files() {
  std::vector<std::string> names;
  for (int i = 0; i < fr_embedded_kernels_count; ++i) {
    std::string_view name = fr_embedded_kernels[i].name;
    if (name.rfind("de/", 0) == 0) names.push_back("fr/" + std::string(name.substr(3)));
  }
  return names;
}

}  // namespace fr
