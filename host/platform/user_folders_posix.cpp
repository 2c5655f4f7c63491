#include "platform/user_folders.hpp"

#include <cstdlib>
#include <system_error>

namespace fr {

std::filesystem::path user_folder(UserFolder kind) {
  const char* variable = "XDG_CACHE_HOME";
  std::filesystem::path under_home = ".cache";
  if (kind == UserFolder::Config) variable = "XDG_CONFIG_HOME", under_home = ".config";
  if (kind == UserFolder::Data) variable = "XDG_DATA_HOME", under_home = ".local/share";
  if (const char* xdg = std::getenv(variable); xdg && *xdg)
    return std::filesystem::path(xdg) / "fractalis";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / under_home / "fractalis";
  return {};
}

void set_environment_variable(const char* name, const std::filesystem::path& value) {
  setenv(name, value.c_str(), 1);
}

std::filesystem::path executable_path() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe;
}

}  // namespace fr
