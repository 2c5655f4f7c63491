// The EXR writer of a build without OpenEXR (FRACTALIS_OPENEXR=OFF: the Windows build, which
// does not cross-build it yet): every EXR output is refused, saying why; PNG is always there.
#include "image/exr_write.hpp"

#include <stdexcept>

namespace fr {

struct ExrStream::State {};

std::string exr_unavailable_reason() {
  return "this build of fractalis has no EXR writer (it was built without OpenEXR); write a "
         ".png instead";
}

ExrStream::ExrStream(OutputFile&, int, int) {
  throw std::runtime_error(exr_unavailable_reason());
}
ExrStream::~ExrStream() = default;
void ExrStream::write_rows(const FrameImage&) {
  throw std::runtime_error(exr_unavailable_reason());
}
void ExrStream::finish() {
  throw std::runtime_error(exr_unavailable_reason());
}

bool write_exr_atomic(const std::filesystem::path& file, const FrameImage&, std::string* error) {
  *error = "cannot write " + file.string() + ": " + exr_unavailable_reason();
  return false;
}

}  // namespace fr
