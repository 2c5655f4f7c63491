#include "image/png_write.hpp"

#include <fcntl.h>
#include <stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace fr {
namespace {

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

bool write_png_atomic(const std::filesystem::path& path, int w, int h,
                      const std::vector<uint8_t>& rgba8, std::string* error) {
  if (w <= 0 || h <= 0 || rgba8.size() != static_cast<size_t>(w) * h * 4) {
    *error = "cannot write " + path.string() + ": image size does not match its pixels";
    return false;
  }
  std::vector<uint8_t> png;
  if (!stbi_write_png_to_func(append_bytes, &png, w, h, 4, rgba8.data(), w * 4)) {
    *error = "cannot write " + path.string() + ": PNG encoding failed";
    return false;
  }
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  std::string hidden_name = path.filename().string();
  hidden_name.insert(hidden_name.begin(), '.');
  hidden_name += ".XXXXXX";
  std::string tmpl = (dir / hidden_name).string();
  int fd = mkstemp(tmpl.data());
  if (fd < 0) {
    *error = "cannot write " + path.string() + ": cannot create a temporary file in " +
             dir.string() + ": " + std::strerror(errno);
    return false;
  }
  auto fail = [&](const char* what) {
    *error = "cannot write " + path.string() + ": " + what + ": " + std::strerror(errno);
    close(fd);
    unlink(tmpl.c_str());
    return false;
  };
  size_t done = 0;
  while (done < png.size()) {
    ssize_t n = write(fd, png.data() + done, png.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail("write failed");
    }
    done += static_cast<size_t>(n);
  }
  if (fchmod(fd, 0644) != 0) return fail("chmod failed");
  if (fsync(fd) != 0) return fail("fsync failed");
  if (close(fd) != 0) {
    *error = "cannot write " + path.string() + ": close failed: " + std::strerror(errno);
    unlink(tmpl.c_str());
    return false;
  }
  if (rename(tmpl.c_str(), path.c_str()) != 0) {
    *error = "cannot write " + path.string() + ": rename failed: " + std::strerror(errno);
    unlink(tmpl.c_str());
    return false;
  }
  return true;
}

}  // namespace fr
