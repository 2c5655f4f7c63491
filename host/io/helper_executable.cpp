#include "io/helper_executable.hpp"

#include "platform/child_process.hpp"
#include "platform/user_folders.hpp"

#include <cstdlib>
#include <vector>

namespace fr {

std::filesystem::path helper_executable(const char* name, const char* env_variable,
                                        const char* build_path) {
  if (const char* env = std::getenv(env_variable); env && *env) return env;
  const std::filesystem::path self = executable_path();
  const std::string file = executable_file_name(name);
  std::vector<std::filesystem::path> candidates;
  if (!self.empty()) {
    candidates.push_back(self.parent_path() / file);
    candidates.push_back(self.parent_path().parent_path() / "libexec" / "fractalis" / file);
  }
  candidates.emplace_back(build_path);
  for (const auto& c : candidates)
    if (is_executable_file(c)) return c;
  return {};
}

}  // namespace fr
