#include "platform/user_folders.hpp"

#include <windows.h>

#include <string>

namespace fr {
namespace {

std::filesystem::path environment_path(const wchar_t* name) {
  const DWORD length = GetEnvironmentVariableW(name, nullptr, 0);
  if (length <= 1) return {};
  std::wstring value(length, L'\0');
  const DWORD got = GetEnvironmentVariableW(name, value.data(), length);
  if (got == 0 || got >= length) return {};
  value.resize(got);
  return std::filesystem::path(value);
}

}  // namespace

std::filesystem::path user_folder(UserFolder kind) {
  // Roaming settings follow the user between machines; caches and scenes stay on this one.
  const std::filesystem::path base =
      environment_path(kind == UserFolder::Config ? L"APPDATA" : L"LOCALAPPDATA");
  if (base.empty()) return {};
  return kind == UserFolder::Cache ? base / "fractalis" / "cache" : base / "fractalis";
}

void set_environment_variable(const char* name, const std::filesystem::path& value) {
  // The C runtime's copy (getenv) and the process's (child processes, GetEnvironmentVariableW).
  _wputenv_s(std::wstring(name, name + std::char_traits<char>::length(name)).c_str(),
             value.c_str());
}

std::filesystem::path executable_path() {
  std::wstring buffer(MAX_PATH, L'\0');
  for (;;) {
    const DWORD got = GetModuleFileNameW(nullptr, buffer.data(), static_cast<DWORD>(buffer.size()));
    if (got == 0) return {};
    if (got < buffer.size()) {
      buffer.resize(got);
      return std::filesystem::path(buffer);
    }
    buffer.resize(buffer.size() * 2);  // a long path (\\?\ prefixed), truncated: try again
  }
}

}  // namespace fr
