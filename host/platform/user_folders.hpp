// user_folders.hpp — where this user's files for fractalis go, and where fractalis itself is.
#pragma once

#include <filesystem>

namespace fr {

enum class UserFolder {
  Cache,   // what can be rebuilt: $XDG_CACHE_HOME or ~/.cache; %LOCALAPPDATA%
  Config,  // settings: $XDG_CONFIG_HOME or ~/.config; %APPDATA%
  Data,    // the user's own scenes: $XDG_DATA_HOME or ~/.local/share; %LOCALAPPDATA%
};

// The system's folder of that kind for this user, with "fractalis" appended; empty when the
// environment names none (no HOME, no %LOCALAPPDATA%).
std::filesystem::path user_folder(UserFolder kind);

// Sets an environment variable of this process (and of the processes it starts later).
void set_environment_variable(const char* name, const std::filesystem::path& value);

// The running executable's own path (to find its helper executables and installed files);
// empty when the system does not say.
std::filesystem::path executable_path();

}  // namespace fr
