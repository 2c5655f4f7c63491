#include "plugin/plugin_files.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace fr {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISLNK(mode)) return "a symlink";
  return "not a regular file";
}

// Why a file or folder with this status could be changed by a user other than us or root.
std::string foreign_writer(const struct stat& st, bool is_folder) {
  const uid_t me = geteuid();
  if (st.st_uid != me && st.st_uid != 0)
    return "owned by user " + std::to_string(st.st_uid) + ", not by you or root";
  // A sticky folder (like /tmp) lets others add entries but not replace or rename ours.
  if (is_folder && (st.st_mode & S_ISVTX)) return "";
  if (st.st_mode & S_IWOTH) return "writable by every user";
  if ((st.st_mode & S_IWGRP) && st.st_gid != getegid())
    return "writable by group " + std::to_string(st.st_gid);
  return "";
}

int64_t nanoseconds(const struct timespec& t) {
  return int64_t{t.tv_sec} * 1000000000 + t.tv_nsec;
}

}  // namespace

std::string writable_by_others(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(folder, ec).lexically_normal();
  if (ec) return "cannot resolve: " + ec.message();
  // The folder itself, then each parent: any of them could be renamed or replaced by its writer.
  for (;;) {
    struct stat st {};
    if (stat(p.c_str(), &st) != 0) return p.string() + ": " + std::strerror(errno);
    if (std::string why = foreign_writer(st, true); !why.empty()) return p.string() + " is " + why;
    if (p == p.root_path() || p.parent_path() == p) return "";
    p = p.parent_path();
  }
}

std::vector<PluginFile> list_plugin_files(const std::filesystem::path& folder,
                                          bool allow_writable) {
  if (!allow_writable) {
    if (std::string why = writable_by_others(folder); !why.empty())
      return {{folder, "plugin folder refused: " + why +
                           " (set plugins.allow_writable = true to load from it anyway)"}};
  }
  DIR* dir = opendir(folder.c_str());
  if (!dir)
    return {{folder, std::string("cannot read the plugin folder: ") + std::strerror(errno)}};
  std::vector<PluginFile> files;
  while (const dirent* e = readdir(dir)) {
    const std::string name = e->d_name;
    if (name.size() < 4 || name.compare(name.size() - 3, 3, ".so") != 0) continue;
    PluginFile f{folder / name, ""};
    struct stat own {
    }, target{};
    // fstatat never opens anything, so FIFOs and devices cannot block the scan.
    if (fstatat(dirfd(dir), e->d_name, &own, AT_SYMLINK_NOFOLLOW) != 0) {
      f.skip_reason = std::string("cannot stat: ") + std::strerror(errno);
    } else if (fstatat(dirfd(dir), e->d_name, &target, 0) != 0) {
      const int err = errno;
      if (S_ISLNK(own.st_mode) && err == ELOOP)
        f.skip_reason = "a symlink loop";
      else if (S_ISLNK(own.st_mode) && err == ENOENT)
        f.skip_reason = "a dangling symlink";
      else
        f.skip_reason = std::string("cannot stat: ") + std::strerror(err);
    } else if (!S_ISREG(target.st_mode)) {
      f.skip_reason = (S_ISLNK(own.st_mode) ? "a symlink to " : "") + kind_of(target.st_mode) +
                      ", not a shared library";
    }
    files.push_back(std::move(f));
  }
  closedir(dir);
  std::sort(files.begin(), files.end(),
            [](const PluginFile& a, const PluginFile& b) { return a.path < b.path; });
  return files;
}

int open_plugin_file(const std::filesystem::path& file, bool allow_writable, std::string* error,
                     FileIdentity* identity) {
  // O_NONBLOCK: a FIFO swapped in after the scan opens without waiting for a writer; the fstat
  // below then refuses it.
  const int fd = open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int err = errno;
    struct stat own {};
    if (err == ELOOP)
      *error = "a symlink loop";
    else if (err == ENOENT && lstat(file.c_str(), &own) == 0 && S_ISLNK(own.st_mode))
      *error = "a dangling symlink";
    else
      *error = std::string("cannot open: ") + std::strerror(err);
    return -1;
  }
  struct stat st {};
  std::string why;
  if (fstat(fd, &st) != 0)
    why = std::string("cannot stat: ") + std::strerror(errno);
  else if (!S_ISREG(st.st_mode))
    why = kind_of(st.st_mode) + ", not a shared library";
  else if (st.st_size > kMaxPluginFileBytes)
    why = std::to_string(st.st_size) + " bytes, more than the " +
          std::to_string(kMaxPluginFileBytes >> 20) + " MiB a scene plugin may have";
  else if (!allow_writable) {
    if (std::string w = foreign_writer(st, false); !w.empty())
      why = "refused: the file is " + w + " (set plugins.allow_writable = true to load it anyway)";
  }
  if (!why.empty()) {
    close(fd);
    *error = why;
    return -1;
  }
  if (identity)
    *identity = {st.st_dev, st.st_ino, st.st_size, nanoseconds(st.st_mtim),
                 nanoseconds(st.st_ctim)};
  return fd;
}

}  // namespace fr
