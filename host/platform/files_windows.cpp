#include "platform/files.hpp"

#include "platform/last_error_windows.hpp"

#include <windows.h>

#include <algorithm>
#include <cstring>

namespace fr {
namespace {

bool failed(std::string* error) {
  *error = last_error_text();
  return false;
}

HANDLE as_handle(intptr_t h) {
  return reinterpret_cast<HANDLE>(h);
}

}  // namespace

PathInfo examine_path(const std::filesystem::path& path) {
  PathInfo info;
  const DWORD attributes = GetFileAttributesW(path.c_str());
  if (attributes == INVALID_FILE_ATTRIBUTES) {
    const DWORD code = GetLastError();
    if (code != ERROR_FILE_NOT_FOUND && code != ERROR_PATH_NOT_FOUND) {
      // NUL, CON and pipes have no attributes to read: ask what a handle to them is.
    } else {
      return info;
    }
  }
  info.is_link =
      attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_REPARSE_POINT);
  // What the path names, links followed: its handle's type.
  const HANDLE h =
      CreateFileW(path.c_str(), 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                  OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (h == INVALID_HANDLE_VALUE) {
    info.error = last_error_text();
    return info;
  }
  switch (GetFileType(h)) {
    case FILE_TYPE_CHAR:
      info.kind = PathKind::CharacterDevice;
      break;
    case FILE_TYPE_PIPE:
      info.kind = PathKind::Pipe;
      break;
    case FILE_TYPE_DISK: {
      BY_HANDLE_FILE_INFORMATION file{};
      info.kind =
          GetFileInformationByHandle(h, &file) && (file.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY)
              ? PathKind::Folder
              : PathKind::Regular;
      break;
    }
    default:
      info.kind = PathKind::Other;
  }
  CloseHandle(h);
  return info;
}

bool is_standard_output_path(const std::filesystem::path& path) {
  const HANDLE out = GetStdHandle(STD_OUTPUT_HANDLE);
  BY_HANDLE_FILE_INFORMATION a{}, b{};
  if (out == nullptr || out == INVALID_HANDLE_VALUE || !GetFileInformationByHandle(out, &a))
    return false;
  const HANDLE h =
      CreateFileW(path.c_str(), 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                  OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (h == INVALID_HANDLE_VALUE) return false;
  const bool same = GetFileInformationByHandle(h, &b) &&
                    a.dwVolumeSerialNumber == b.dwVolumeSerialNumber &&
                    a.nFileIndexHigh == b.nFileIndexHigh && a.nFileIndexLow == b.nFileIndexLow;
  CloseHandle(h);
  return same;
}

bool can_write_in(const std::filesystem::path& folder) {
  // Access control lists decide, with more rules than a bit to read: try it.
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::filesystem::path probe =
        folder / (".fractalis-write-probe-" + std::to_string(GetCurrentProcessId()) + "-" +
                  std::to_string(GetTickCount64() + attempt));
    const HANDLE h = CreateFileW(probe.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW,
                                 FILE_ATTRIBUTE_TEMPORARY | FILE_FLAG_DELETE_ON_CLOSE, nullptr);
    if (h != INVALID_HANDLE_VALUE) {
      CloseHandle(h);
      return true;
    }
    if (GetLastError() != ERROR_FILE_EXISTS) return false;
  }
  return false;
}

unsigned new_file_mode() {
  return 0;  // no permission bits: a new file inherits its folder's access control list
}

uint64_t current_process_id() {
  return GetCurrentProcessId();
}

WritableFile::~WritableFile() {
  if (handle_ != kNone) CloseHandle(as_handle(handle_));
}

WritableFile::WritableFile(WritableFile&& other) noexcept : handle_(other.handle_) {
  other.handle_ = kNone;
}

WritableFile& WritableFile::operator=(WritableFile&& other) noexcept {
  if (this != &other) {
    if (handle_ != kNone) CloseHandle(as_handle(handle_));
    handle_ = other.handle_;
    other.handle_ = kNone;
  }
  return *this;
}

WritableFile WritableFile::create_new(const std::filesystem::path& path, bool* exists,
                                      std::string* error) {
  // Not inherited by child processes (the default for a handle without SECURITY_ATTRIBUTES).
  const HANDLE h = CreateFileW(path.c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_DELETE,
                               nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr);
  *exists = h == INVALID_HANDLE_VALUE && GetLastError() == ERROR_FILE_EXISTS;
  if (h == INVALID_HANDLE_VALUE) {
    failed(error);
    return WritableFile();
  }
  return WritableFile(reinterpret_cast<intptr_t>(h));
}

WritableFile WritableFile::open_existing(const std::filesystem::path& path, std::string* error) {
  const HANDLE h = CreateFileW(path.c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE,
                               nullptr, OPEN_EXISTING, FILE_ATTRIBUTE_NORMAL, nullptr);
  if (h == INVALID_HANDLE_VALUE) {
    failed(error);
    return WritableFile();
  }
  return WritableFile(reinterpret_cast<intptr_t>(h));
}

bool WritableFile::write_all(std::string_view bytes, std::string* error) {
  size_t done = 0;
  while (done < bytes.size()) {
    const DWORD chunk = static_cast<DWORD>(std::min<size_t>(bytes.size() - done, 1u << 30));
    DWORD written = 0;
    if (!WriteFile(as_handle(handle_), bytes.data() + done, chunk, &written, nullptr))
      return failed(error);
    done += written;
  }
  return true;
}

bool WritableFile::seek(uint64_t offset, std::string* error) {
  LARGE_INTEGER to;
  to.QuadPart = static_cast<LONGLONG>(offset);
  return SetFilePointerEx(as_handle(handle_), to, nullptr, FILE_BEGIN) || failed(error);
}

bool WritableFile::set_mode(unsigned, std::string*) {
  return true;
}

bool WritableFile::flush_to_disk(std::string* error) {
  return FlushFileBuffers(as_handle(handle_)) || failed(error);
}

bool WritableFile::close(std::string* error) {
  const HANDLE h = as_handle(handle_);
  handle_ = kNone;
  return CloseHandle(h) || failed(error);
}

bool replace_file(const std::filesystem::path& from, const std::filesystem::path& to,
                  std::string* error) {
  return MoveFileExW(from.c_str(), to.c_str(),
                     MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) ||
         failed(error);
}

void remove_file_now(const char* path) {
  DeleteFileA(path);
}

void write_stderr_now(const char* text) {
  DWORD written = 0;
  WriteFile(GetStdHandle(STD_ERROR_HANDLE), text, static_cast<DWORD>(strlen(text)), &written,
            nullptr);
}

}  // namespace fr
