#include "platform/shared_library.hpp"

#include "platform/last_error_windows.hpp"
#include "platform/user_folders.hpp"

#include <windows.h>
// (after windows.h)
#include <tlhelp32.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <cwctype>
#include <random>
#include <string>
#include <vector>

namespace fr {
namespace {

template <typename T>
bool read_struct(const std::string& bytes, uint64_t at, T* out) {
  if (at > bytes.size() || bytes.size() - at < sizeof(T)) return false;
  std::memcpy(out, bytes.data() + at, sizeof(T));
  return true;
}

const char* machine_name(WORD machine) {
  switch (machine) {
    case IMAGE_FILE_MACHINE_AMD64:
      return "x86-64";
    case IMAGE_FILE_MACHINE_I386:
      return "i386";
    case IMAGE_FILE_MACHINE_ARM64:
      return "ARM64";
    case IMAGE_FILE_MACHINE_ARMNT:
      return "ARM";
    default:
      return nullptr;
  }
}

std::string describe_machine(WORD machine) {
  const char* name = machine_name(machine);
  return name ? name : "PE machine " + std::to_string(machine);
}

// This process's own machine, from its executable's headers in memory.
WORD host_machine() {
  const auto* base = reinterpret_cast<const unsigned char*>(GetModuleHandleW(nullptr));
  const auto* dos = reinterpret_cast<const IMAGE_DOS_HEADER*>(base);
  const auto* nt = reinterpret_cast<const IMAGE_NT_HEADERS*>(base + dos->e_lfanew);
  return nt->FileHeader.Machine;
}

// Where the private copies go: a folder of this user's, created on first use.
std::filesystem::path copies_folder(std::string* error) {
  const std::filesystem::path base = user_folder(UserFolder::Cache);
  if (base.empty()) {
    *error = "cannot make a private copy: no %LOCALAPPDATA%";
    return {};
  }
  const std::filesystem::path folder = base / "plugin-copies";
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) {
    *error = "cannot make a private copy in " + folder.string() + ": " + ec.message();
    return {};
  }
  return folder;
}

// Copies a process that ended abruptly left behind. A copy still loaded somewhere cannot be
// removed, and stays; one younger than a minute may be another scene host's between being
// written and being loaded (the scans run several at once), and is left alone.
void remove_stale_copies(const std::filesystem::path& folder) {
  std::error_code ec;
  const auto now = std::filesystem::file_time_type::clock::now();
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    std::error_code time_ec;
    const auto written = entry.last_write_time(time_ec);
    if (entry.path().extension() == ".dll" && !time_ec && now - written > std::chrono::minutes(1))
      DeleteFileW(entry.path().c_str());
  }
}

// The DLLs a checked library's import table names (check_library_bytes passed it), as written.
std::vector<std::string> imported_dll_names(const std::string& bytes) {
  IMAGE_DOS_HEADER dos{};
  IMAGE_FILE_HEADER file{};
  IMAGE_OPTIONAL_HEADER optional{};
  read_struct(bytes, 0, &dos);
  const uint64_t nt_at = static_cast<uint32_t>(dos.e_lfanew);
  const uint64_t optional_at = nt_at + 4 + sizeof(IMAGE_FILE_HEADER);
  if (!read_struct(bytes, nt_at + 4, &file) || !read_struct(bytes, optional_at, &optional))
    return {};
  if (optional.NumberOfRvaAndSizes <= IMAGE_DIRECTORY_ENTRY_IMPORT) return {};
  std::vector<IMAGE_SECTION_HEADER> sections(file.NumberOfSections);
  for (size_t i = 0; i < sections.size(); ++i)
    if (!read_struct(bytes, optional_at + file.SizeOfOptionalHeader + i * sizeof sections[i],
                     &sections[i]))
      return {};
  // A relative virtual address as an offset into the file: through the section that holds it.
  const auto file_offset = [&](uint64_t rva) -> uint64_t {
    for (const auto& s : sections)
      if (rva >= s.VirtualAddress && rva < uint64_t{s.VirtualAddress} + s.SizeOfRawData)
        return rva - s.VirtualAddress + s.PointerToRawData;
    return UINT64_MAX;
  };
  std::vector<std::string> names;
  uint64_t at = file_offset(optional.DataDirectory[IMAGE_DIRECTORY_ENTRY_IMPORT].VirtualAddress);
  IMAGE_IMPORT_DESCRIPTOR import{};
  while (names.size() < 256 && read_struct(bytes, at, &import) && import.Name != 0) {
    const uint64_t name_at = file_offset(import.Name);
    if (name_at >= bytes.size()) break;
    const size_t end = bytes.find('\0', name_at);
    if (end == std::string::npos) break;
    names.push_back(bytes.substr(name_at, std::min<size_t>(end - name_at, 260)));
    at += sizeof import;
  }
  return names;
}

// Which DLLs a library needs that are in none of the folders its load searched (this program's
// folder and the system's), for a failed load's message: Windows says only "module not found".
// (The copy's own folder holds no other DLL.)
std::string missing_dlls(const std::string& bytes) {
  std::vector<std::filesystem::path> searched;
  wchar_t path[MAX_PATH];
  if (GetModuleFileNameW(nullptr, path, MAX_PATH) > 0)
    searched.push_back(std::filesystem::path(path).parent_path());
  if (GetSystemDirectoryW(path, MAX_PATH) > 0) searched.push_back(path);
  std::string missing;
  for (const std::string& name : imported_dll_names(bytes)) {
    if (name.rfind("api-ms-", 0) == 0 || name.rfind("ext-ms-", 0) == 0) continue;  // API sets
    const std::filesystem::path file(std::wstring(name.begin(), name.end()));
    std::error_code ec;
    if (!std::any_of(searched.begin(), searched.end(), [&](const auto& folder) {
          return std::filesystem::exists(folder / file, ec);
        }))
      missing += (missing.empty() ? "" : ", ") + name;
  }
  return missing;
}

}  // namespace

std::string check_library_bytes(const std::string& bytes) {
  const uint64_t size = bytes.size();
  IMAGE_DOS_HEADER dos{};
  if (!read_struct(bytes, 0, &dos) || dos.e_magic != IMAGE_DOS_SIGNATURE) {
    char hex[32] = "fewer than 2 bytes";
    if (size >= 2)
      std::snprintf(hex, sizeof hex, "%02x %02x", static_cast<unsigned char>(bytes[0]),
                    static_cast<unsigned char>(bytes[1]));
    return std::string("not a Windows DLL (expected bytes 4d 5a, found ") + hex + ")";
  }
  DWORD signature = 0;
  IMAGE_FILE_HEADER file{};
  const uint64_t nt_at = static_cast<uint64_t>(static_cast<uint32_t>(dos.e_lfanew));
  if (!read_struct(bytes, nt_at, &signature) || !read_struct(bytes, nt_at + 4, &file))
    return "truncated: " + std::to_string(size) + " bytes, shorter than its PE header";
  if (signature != IMAGE_NT_SIGNATURE) return "not a Windows DLL (no PE signature)";
  if (file.Machine != host_machine())
    return "built for " + describe_machine(file.Machine) + "; this host is " +
           describe_machine(host_machine());
  if (!(file.Characteristics & IMAGE_FILE_DLL)) return "not a DLL (a program or an object file)";
  const uint64_t optional_at = nt_at + 4 + sizeof(IMAGE_FILE_HEADER);
  IMAGE_OPTIONAL_HEADER optional{};
  if (file.SizeOfOptionalHeader < sizeof optional || !read_struct(bytes, optional_at, &optional))
    return "truncated: " + std::to_string(size) + " bytes, shorter than its optional header";
  if (optional.SizeOfHeaders > size)
    return "truncated: " + std::to_string(size) + " bytes, but its headers end at byte " +
           std::to_string(optional.SizeOfHeaders);
  const uint64_t sections_at = optional_at + file.SizeOfOptionalHeader;
  for (unsigned i = 0; i < file.NumberOfSections; ++i) {
    IMAGE_SECTION_HEADER section{};
    if (!read_struct(bytes, sections_at + uint64_t{i} * sizeof section, &section))
      return "truncated section table";
    const uint64_t end = uint64_t{section.PointerToRawData} + section.SizeOfRawData;
    if (section.SizeOfRawData > 0 && end > size)
      return "truncated: " + std::to_string(size) + " bytes, but a section ends at byte " +
             std::to_string(end);
  }
  return "";
}

std::unique_ptr<SharedLibrary> SharedLibrary::load_private_copy(
    const std::string& bytes, const std::filesystem::path& named_as, std::string* error) {
  if (std::string problem = check_library_bytes(bytes); !problem.empty()) {
    *error = problem;
    return nullptr;
  }
  const std::filesystem::path folder = copies_folder(error);
  if (folder.empty()) return nullptr;
  remove_stale_copies(folder);
  static std::atomic<unsigned> serial{0};
  std::random_device random;
  std::filesystem::path copy;
  HANDLE file = INVALID_HANDLE_VALUE;
  for (int attempt = 0; attempt < 8 && file == INVALID_HANDLE_VALUE; ++attempt) {
    copy = folder / (std::to_string(GetCurrentProcessId()) + "-" + std::to_string(serial++) + "-" +
                     std::to_string(random()) + std::to_string(random()) + ".dll");
    file = CreateFileW(copy.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW,
                       FILE_ATTRIBUTE_TEMPORARY, nullptr);
  }
  if (file == INVALID_HANDLE_VALUE) {
    *error = "cannot make a private copy: " + last_error_text();
    return nullptr;
  }
  bool written = true;
  for (size_t done = 0; done < bytes.size() && written;) {
    DWORD n = 0;
    const DWORD chunk = static_cast<DWORD>(std::min<size_t>(bytes.size() - done, 1u << 30));
    written = WriteFile(file, bytes.data() + done, chunk, &n, nullptr) && n > 0;
    done += n;
  }
  if (!written) *error = "cannot copy: " + last_error_text();
  CloseHandle(file);
  if (!written) {
    DeleteFileW(copy.c_str());
    return nullptr;
  }
  // Held open for reading only, sharing reading only, until the loader has mapped it: nobody can
  // change or replace the copy in between (the folder is the user's own, so only their own
  // processes could have tried since it was written).
  const HANDLE guard =
      CreateFileW(copy.c_str(), GENERIC_READ, FILE_SHARE_READ, nullptr, OPEN_EXISTING, 0, nullptr);
  if (guard == INVALID_HANDLE_VALUE) {
    *error = "cannot open the private copy: " + last_error_text();
    DeleteFileW(copy.c_str());
    return nullptr;
  }
  // Only the copy's own folder and the system's are searched for the DLLs it needs.
  const HMODULE module = LoadLibraryExW(
      copy.c_str(), nullptr, LOAD_LIBRARY_SEARCH_DLL_LOAD_DIR | LOAD_LIBRARY_SEARCH_DEFAULT_DIRS);
  if (!module) {
    const DWORD code = GetLastError();
    *error = "LoadLibrary failed for " + named_as.string() + ": " + last_error_text();
    if (code == ERROR_MOD_NOT_FOUND) {
      if (const std::string missing = missing_dlls(bytes); !missing.empty())
        *error += " (it needs " + missing +
                  ", found neither in the system folder nor beside the scene host)";
    }
  }
  CloseHandle(guard);
  if (!module) {
    DeleteFileW(copy.c_str());
    return nullptr;
  }
  std::unique_ptr<SharedLibrary> library(new SharedLibrary());
  library->handle_ = module;
  library->copy_path_ = copy;
  return library;
}

SharedLibrary::~SharedLibrary() {
  FreeLibrary(static_cast<HMODULE>(handle_));
  DeleteFileW(copy_path_.c_str());
}

const void* SharedLibrary::symbol(const char* name) const {
  return reinterpret_cast<const void*>(GetProcAddress(static_cast<HMODULE>(handle_), name));
}

size_t private_copy_mappings() {
  std::string error;
  const std::filesystem::path folder = copies_folder(&error);
  if (folder.empty()) return 0;
  const HANDLE all = CreateToolhelp32Snapshot(TH32CS_SNAPMODULE, 0);
  if (all == INVALID_HANDLE_VALUE) return 0;
  MODULEENTRY32W entry{};
  entry.dwSize = sizeof entry;
  size_t n = 0;
  std::error_code ec;
  for (BOOL more = Module32FirstW(all, &entry); more; more = Module32NextW(all, &entry))
    if (std::filesystem::equivalent(std::filesystem::path(entry.szExePath).parent_path(), folder,
                                    ec))
      ++n;
  CloseHandle(all);
  return n;
}

std::string library_file_name(const std::string& name) {
  return name + ".dll";
}

bool is_library_file_name(const std::filesystem::path& file) {
  std::wstring extension = file.extension().wstring();
  for (wchar_t& c : extension) c = static_cast<wchar_t>(std::towlower(c));
  return extension == L".dll" && !file.stem().empty();
}

}  // namespace fr
