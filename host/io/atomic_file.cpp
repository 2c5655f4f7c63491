#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace fr {

bool write_file_atomic(const std::filesystem::path& path, std::string_view bytes,
                       std::string* error) {
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
  while (done < bytes.size()) {
    ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
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
