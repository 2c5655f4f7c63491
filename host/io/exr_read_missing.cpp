// The EXR reader of a build without OpenEXR (FRACTALIS_OPENEXR=OFF: the Windows build): an .exr
// panorama is refused, saying why; a Radiance .hdr is always read.
#include "io/environment_image.hpp"

namespace fr {

bool read_exr_rgb(const std::filesystem::path& path, int, EnvironmentImage* image,
                  std::string* error) {
  *image = EnvironmentImage{};
  *error = "cannot read " + path.string() +
           ": this build of fractalis has no OpenEXR reader; convert it to a Radiance .hdr";
  return false;
}

}  // namespace fr
