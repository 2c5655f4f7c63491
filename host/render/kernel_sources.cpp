#include "render/kernel_sources.hpp"

#include <stdexcept>
#include <string>

// Defined in the generated embedded_kernels.c (see host/CMakeLists.txt).
extern "C" {
extern const char fr_kernel_frame_constants_h[];
extern const char fr_kernel_prelude_cl[];
extern const char fr_kernel_rays_cl[];
extern const char fr_kernel_march_cl[];
extern const char fr_kernel_normals_cl[];
extern const char fr_kernel_shadow_cl[];
extern const char fr_kernel_ao_cl[];
extern const char fr_kernel_shade_cl[];
extern const char fr_kernel_render_cl[];
extern const char fr_kernel_post_cl[];
extern const char fr_kernel_probe_cl[];
}

namespace fr {

std::string_view kernel_source(std::string_view name) {
  struct Entry {
    std::string_view name;
    const char* text;
  };
  static const Entry entries[] = {
      {"frame_constants.h", fr_kernel_frame_constants_h},
      {"prelude.cl", fr_kernel_prelude_cl},
      {"rays.cl", fr_kernel_rays_cl},
      {"march.cl", fr_kernel_march_cl},
      {"normals.cl", fr_kernel_normals_cl},
      {"shadow.cl", fr_kernel_shadow_cl},
      {"ao.cl", fr_kernel_ao_cl},
      {"shade.cl", fr_kernel_shade_cl},
      {"render.cl", fr_kernel_render_cl},
      {"post.cl", fr_kernel_post_cl},
      {"probe.cl", fr_kernel_probe_cl},
  };
  for (const auto& e : entries)
    if (e.name == name) return e.text;
  throw std::out_of_range("no embedded kernel file named " + std::string(name));
}

}  // namespace fr
