#include "platform/files.hpp"

#include "platform/last_error_windows.hpp"

#include <windows.h>
// After windows.h:
#include <aclapi.h>
#include <sddl.h>

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
  info.is_link =
      attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_REPARSE_POINT);
  // What the path names, links followed: its handle's type. Asked even where the attributes
  // said "not found": NUL, CON and pipes have no attributes to read (Wine says NUL is not
  // found), and a missing file costs one more failed call.
  const HANDLE h =
      CreateFileW(path.c_str(), 0, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                  OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (h == INVALID_HANDLE_VALUE) {
    const DWORD code = GetLastError();
    if (code == ERROR_FILE_NOT_FOUND || code == ERROR_PATH_NOT_FOUND) return info;
    info.loops = code == ERROR_CANT_RESOLVE_FILENAME;
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

namespace {

// A SID's account name ("BUILTIN\\Users"), or its string form when it has none.
std::string account_name(PSID sid) {
  wchar_t name[256], domain[256];
  DWORD name_size = 256, domain_size = 256;
  SID_NAME_USE use;
  if (LookupAccountSidW(nullptr, sid, name, &name_size, domain, &domain_size, &use)) {
    const std::wstring full = domain_size ? std::wstring(domain) + L"\\" + name : name;
    return std::filesystem::path(full).string();
  }
  char* text = nullptr;
  if (!ConvertSidToStringSidA(sid, &text)) return "an unknown account";
  std::string out = text;
  LocalFree(text);
  return out;
}

struct WellKnownSid {
  BYTE bytes[SECURITY_MAX_SID_SIZE];
  bool made = false;
  explicit WellKnownSid(WELL_KNOWN_SID_TYPE type) {
    DWORD size = sizeof bytes;
    made = CreateWellKnownSid(type, nullptr, bytes, &size);
  }
  bool is(PSID sid) const { return made && EqualSid(const_cast<BYTE*>(bytes), sid); }
};

bool is_this_user(PSID sid) {
  HANDLE token = nullptr;
  if (!OpenProcessToken(GetCurrentProcess(), TOKEN_QUERY, &token)) return false;
  BYTE buffer[sizeof(TOKEN_USER) + SECURITY_MAX_SID_SIZE];
  DWORD size = 0;
  const bool same = GetTokenInformation(token, TokenUser, buffer, sizeof buffer, &size) &&
                    EqualSid(reinterpret_cast<TOKEN_USER*>(buffer)->User.Sid, sid);
  CloseHandle(token);
  return same;
}

// Windows' own installer service, which owns the system's folders.
bool is_trusted_installer(PSID sid) {
  PSID installer = nullptr;
  if (!ConvertStringSidToSidW(L"S-1-5-80-956008885-3418522649-1831038044-1853292631-2271478464",
                              &installer))
    return false;
  const bool same = EqualSid(installer, sid);
  LocalFree(installer);
  return same;
}

// The POSIX side's rule in access-control terms: the owner is this user, the Administrators or
// the system; and no group of other users may change the file (write it, or replace its access
// rules or owner, or delete it) or, for a folder, delete or rename what is in it. Adding an entry
// to a folder is not refused (like a sticky folder): the entry is then someone else's, which the
// owner rule refuses.
std::string foreign_writer(PSID owner, PACL dacl, bool is_folder) {
  static const WellKnownSid administrators(WinBuiltinAdministratorsSid), system(WinLocalSystemSid);
  if (owner && !is_this_user(owner) && !administrators.is(owner) && !system.is(owner) &&
      !is_trusted_installer(owner))
    return "owned by " + account_name(owner) + ", not by you or an administrator";
  if (!dacl) return "open to every user (it has no access control list)";
  static const WellKnownSid everyone(WinWorldSid), users(WinBuiltinUsersSid),
      authenticated(WinAuthenticatedUserSid), guests(WinBuiltinGuestsSid),
      anonymous(WinAnonymousSid);
  const ACCESS_MASK changes =
      WRITE_DAC | WRITE_OWNER | DELETE | GENERIC_ALL |
      (is_folder ? FILE_DELETE_CHILD : FILE_WRITE_DATA | FILE_APPEND_DATA | GENERIC_WRITE);
  for (DWORD i = 0; i < dacl->AceCount; ++i) {
    void* ace = nullptr;
    if (!GetAce(dacl, i, &ace)) continue;
    const auto* header = static_cast<const ACE_HEADER*>(ace);
    if (header->AceType != ACCESS_ALLOWED_ACE_TYPE || (header->AceFlags & INHERIT_ONLY_ACE))
      continue;
    auto* allowed = static_cast<ACCESS_ALLOWED_ACE*>(ace);
    PSID sid = &allowed->SidStart;
    if (!(allowed->Mask & changes)) continue;
    for (const WellKnownSid* group : {&everyone, &users, &authenticated, &guests, &anonymous})
      if (group->is(sid)) return "writable by " + account_name(sid);
  }
  return "";
}

int64_t file_time_ns(LARGE_INTEGER t) {
  return t.QuadPart * 100;  // 100 ns units since 1601
}

}  // namespace

std::optional<FileIdentity> identity_of(const std::filesystem::path& path, std::string* error) {
  WIN32_FILE_ATTRIBUTE_DATA data{};
  if (!GetFileAttributesExW(path.c_str(), GetFileExInfoStandard, &data)) {
    *error = "cannot examine " + path.string() + ": " + last_error_text();
    return std::nullopt;
  }
  const auto ns = [](FILETIME t) {
    LARGE_INTEGER v;
    v.LowPart = t.dwLowDateTime;
    v.HighPart = static_cast<LONG>(t.dwHighDateTime);
    return file_time_ns(v);
  };
  FileIdentity id;
  id.size_bytes = (uint64_t{data.nFileSizeHigh} << 32) | data.nFileSizeLow;
  id.mtime_ns = ns(data.ftLastWriteTime);
  id.ctime_ns = ns(data.ftCreationTime);
  return id;
}

std::string others_who_can_write(const std::filesystem::path& path, bool is_folder) {
  PSID owner = nullptr;
  PACL dacl = nullptr;
  PSECURITY_DESCRIPTOR sd = nullptr;
  const DWORD code = GetNamedSecurityInfoW(path.c_str(), SE_FILE_OBJECT,
                                           OWNER_SECURITY_INFORMATION | DACL_SECURITY_INFORMATION,
                                           &owner, nullptr, &dacl, nullptr, &sd);
  if (code != ERROR_SUCCESS) {
    SetLastError(code);
    return "cannot read its access control list: " + last_error_text();
  }
  std::string why = foreign_writer(owner, dacl, is_folder);
  LocalFree(sd);
  return why;
}

ReadableFile::~ReadableFile() {
  if (handle_ != kNone) CloseHandle(as_handle(handle_));
}

ReadableFile ReadableFile::open(const std::filesystem::path& path, std::string* error) {
  // Not inherited (no SECURITY_ATTRIBUTES); folders open too (backup semantics), so that kind()
  // says what they are; others may go on reading, writing or deleting the file meanwhile.
  const HANDLE h = CreateFileW(path.c_str(), GENERIC_READ,
                               FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr,
                               OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (h == INVALID_HANDLE_VALUE) {
    const DWORD code = GetLastError();
    const std::string why = last_error_text();
    const DWORD attributes = GetFileAttributesW(path.c_str());
    if (code == ERROR_CANT_RESOLVE_FILENAME)
      *error = "a symlink loop";
    else if ((code == ERROR_FILE_NOT_FOUND || code == ERROR_PATH_NOT_FOUND) &&
             attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_REPARSE_POINT))
      *error = "a dangling symlink";
    else
      *error = "cannot open: " + why;
    return ReadableFile();
  }
  return adopt(reinterpret_cast<intptr_t>(h), error);
}

ReadableFile ReadableFile::adopt(intptr_t handle, std::string* error) {
  ReadableFile file;
  file.handle_ = handle;
  const HANDLE h = as_handle(handle);
  switch (GetFileType(h)) {
    case FILE_TYPE_CHAR:
      file.kind_ = PathKind::CharacterDevice;
      return file;
    case FILE_TYPE_PIPE:
      file.kind_ = PathKind::Pipe;
      return file;
    case FILE_TYPE_DISK:
      break;
    default:
      file.kind_ = PathKind::Other;
      return file;
  }
  BY_HANDLE_FILE_INFORMATION info{};
  FILE_BASIC_INFO basic{};
  if (!GetFileInformationByHandle(h, &info) ||
      !GetFileInformationByHandleEx(h, FileBasicInfo, &basic, sizeof basic)) {
    *error = "cannot examine the open file: " + last_error_text();
    return ReadableFile();
  }
  file.kind_ =
      (info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY) ? PathKind::Folder : PathKind::Regular;
  file.identity_ = {info.dwVolumeSerialNumber,
                    (uint64_t{info.nFileIndexHigh} << 32) | info.nFileIndexLow,
                    (uint64_t{info.nFileSizeHigh} << 32) | info.nFileSizeLow,
                    file_time_ns(basic.LastWriteTime), file_time_ns(basic.ChangeTime)};
  return file;
}

std::string ReadableFile::others_who_can_write() const {
  PSID owner = nullptr;
  PACL dacl = nullptr;
  PSECURITY_DESCRIPTOR sd = nullptr;
  const DWORD code = GetSecurityInfo(as_handle(handle_), SE_FILE_OBJECT,
                                     OWNER_SECURITY_INFORMATION | DACL_SECURITY_INFORMATION, &owner,
                                     nullptr, &dacl, nullptr, &sd);
  if (code != ERROR_SUCCESS) {
    SetLastError(code);
    return "cannot read its access control list: " + last_error_text();
  }
  std::string why = foreign_writer(owner, dacl, kind_ == PathKind::Folder);
  LocalFree(sd);
  return why;
}

bool ReadableFile::read_all(uint64_t max_bytes, std::string* bytes, std::string* error) const {
  bytes->clear();
  char buffer[1 << 16];
  for (;;) {
    // At an offset, like pread: the position is not the point.
    OVERLAPPED at{};
    at.Offset = static_cast<DWORD>(bytes->size());
    at.OffsetHigh = static_cast<DWORD>(static_cast<uint64_t>(bytes->size()) >> 32);
    DWORD n = 0;
    if (!ReadFile(as_handle(handle_), buffer, sizeof buffer, &n, &at)) {
      if (GetLastError() == ERROR_HANDLE_EOF) return true;
      *error = "cannot read: " + last_error_text();
      return false;
    }
    if (n == 0) return true;
    if (bytes->size() + n > max_bytes) {
      *error = "more than " + std::to_string(max_bytes) + " bytes";
      return false;
    }
    bytes->append(buffer, n);
  }
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
