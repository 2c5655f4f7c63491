#include "plugin/plugin_files.hpp"

#include "platform/shared_library.hpp"

#include <algorithm>

namespace fr {

std::string writable_by_others(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(folder, ec).lexically_normal();
  if (ec) return "cannot resolve: " + ec.message();
  // The folder itself, then each parent: any of them could be renamed or replaced by its writer.
  for (;;) {
    const std::string why = others_who_can_write(p, true);
    if (why.rfind("cannot ", 0) == 0) return p.string() + ": " + why;
    if (!why.empty()) return p.string() + " is " + why;
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
  std::error_code ec;
  std::filesystem::directory_iterator entries(folder, ec);
  if (ec) return {{folder, "cannot read the plugin folder: " + ec.message()}};
  std::vector<PluginFile> files;
  for (; entries != std::filesystem::directory_iterator(); entries.increment(ec)) {
    const std::filesystem::path& path = entries->path();
    if (!is_library_file_name(path)) continue;
    PluginFile f{path, ""};
    // Examining a path never opens it, so FIFOs and devices cannot block the scan.
    const PathInfo info = examine_path(path);
    if (info.kind == PathKind::Missing) {
      if (info.loops)
        f.skip_reason = "a symlink loop";
      else if (info.is_link)
        f.skip_reason = "a dangling symlink";
      else
        f.skip_reason = "cannot stat: " + (info.error.empty() ? "it is gone" : info.error);
    } else if (info.kind != PathKind::Regular) {
      f.skip_reason =
          (info.is_link ? "a symlink to " : "") + describe(info.kind) + ", not a shared library";
    }
    files.push_back(std::move(f));
  }
  if (ec) return {{folder, "cannot read the plugin folder: " + ec.message()}};
  std::sort(files.begin(), files.end(),
            [](const PluginFile& a, const PluginFile& b) { return a.path < b.path; });
  return files;
}

ReadableFile open_plugin_file(const std::filesystem::path& file, bool allow_writable,
                              std::string* error) {
  ReadableFile opened = ReadableFile::open(file, error);
  if (!opened.valid()) return opened;
  std::string why;
  if (opened.kind() != PathKind::Regular)
    why = describe(opened.kind()) + ", not a shared library";
  else if (opened.identity().size_bytes > kMaxPluginFileBytes)
    why = std::to_string(opened.identity().size_bytes) + " bytes, more than the " +
          std::to_string(kMaxPluginFileBytes >> 20) + " MiB a scene plugin may have";
  else if (!allow_writable) {
    if (std::string w = opened.others_who_can_write(); !w.empty())
      why = "the file is " + w + " (set plugins.allow_writable = true to load it anyway)";
  }
  if (!why.empty()) {
    *error = why;
    return ReadableFile();
  }
  return opened;
}

}  // namespace fr
