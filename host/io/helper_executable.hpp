// helper_executable.hpp — where fractalis finds its helper programs (the scene host, the render
// worker), which platform/child_process.hpp then starts.
#pragma once

#include <filesystem>

namespace fr {

// A helper executable of fractalis: $ENV_VARIABLE when set, else beside the running executable,
// else in ../libexec/fractalis/ from it, else `build_path` (the build tree's). `name` is without
// the system's suffix (.exe on Windows). Empty when none of them exists.
std::filesystem::path helper_executable(const char* name, const char* env_variable,
                                        const char* build_path);

}  // namespace fr
