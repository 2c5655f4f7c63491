#include "platform/system_facts.hpp"

#include <windows.h>
// (after windows.h)
#include <tlhelp32.h>

#include <string>

namespace fr {
namespace {

std::string narrow(const std::wstring& wide) {
  if (wide.empty()) return "";
  const int n = WideCharToMultiByte(CP_UTF8, 0, wide.data(), static_cast<int>(wide.size()), nullptr,
                                    0, nullptr, nullptr);
  std::string out(static_cast<size_t>(n), '\0');
  WideCharToMultiByte(CP_UTF8, 0, wide.data(), static_cast<int>(wide.size()), out.data(), n,
                      nullptr, nullptr);
  return out;
}

// A REG_SZ value under HKEY_LOCAL_MACHINE; "" when absent.
std::string registry_text(const wchar_t* key, const wchar_t* value) {
  wchar_t buffer[512];
  DWORD bytes = sizeof buffer;
  if (RegGetValueW(HKEY_LOCAL_MACHINE, key, value, RRF_RT_REG_SZ, nullptr, buffer, &bytes) !=
      ERROR_SUCCESS)
    return "";
  std::string text = narrow(buffer);
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

}  // namespace

SystemFacts system_facts() {
  SystemFacts s;
  s.cpu_model =
      registry_text(L"HARDWARE\\DESCRIPTION\\System\\CentralProcessor\\0", L"ProcessorNameString");
  if (s.cpu_model.empty()) s.cpu_model = "unknown";
  MEMORYSTATUSEX memory{};
  memory.dwLength = sizeof memory;
  if (GlobalMemoryStatusEx(&memory)) s.memory_bytes = memory.ullTotalPhys;
  // GetVersionEx answers what the manifest claims; ntdll's RtlGetVersion answers the truth.
  using RtlGetVersionFn = LONG(WINAPI*)(OSVERSIONINFOW*);
  OSVERSIONINFOW v{};
  v.dwOSVersionInfoSize = sizeof v;
  const HMODULE ntdll = GetModuleHandleW(L"ntdll.dll");
  const auto get_version = ntdll ? reinterpret_cast<RtlGetVersionFn>(reinterpret_cast<void*>(
                                       GetProcAddress(ntdll, "RtlGetVersion")))
                                 : nullptr;
  const std::string product =
      registry_text(L"SOFTWARE\\Microsoft\\Windows NT\\CurrentVersion", L"ProductName");
  s.os = product.empty() ? "Windows" : product;
  if (get_version && get_version(&v) == 0)
    s.os += ", " + std::to_string(v.dwMajorVersion) + "." + std::to_string(v.dwMinorVersion) + "." +
            std::to_string(v.dwBuildNumber);
  SYSTEM_INFO info{};
  GetNativeSystemInfo(&info);
  s.os += info.wProcessorArchitecture == PROCESSOR_ARCHITECTURE_AMD64   ? " x86-64"
          : info.wProcessorArchitecture == PROCESSOR_ARCHITECTURE_ARM64 ? " ARM64"
                                                                        : "";
  return s;
}

std::vector<MemoryBound> memory_bounds() {
  std::vector<MemoryBound> bounds;
  MEMORYSTATUSEX memory{};
  memory.dwLength = sizeof memory;
  if (GlobalMemoryStatusEx(&memory)) {
    // Committed memory beyond RAM goes to the page file: the commit limit is the bound.
    bounds.push_back({memory.ullAvailPageFile, "the memory available (commit limit left)", 0});
    bounds.push_back({memory.ullAvailVirtual, "the address space left", 0});
  }
  return bounds;
}

uint64_t heap_bytes_in_use() {
  // Every heap of the process: the C runtime's malloc (a plugin DLL's too) allocates from one of
  // them. Walked under each heap's lock, so the sum is of a consistent state per heap.
  HANDLE heaps[64];
  const DWORD count = GetProcessHeaps(64, heaps);
  uint64_t busy = 0;
  for (DWORD i = 0; i < count && i < 64; ++i) {
    if (!HeapLock(heaps[i])) continue;
    PROCESS_HEAP_ENTRY entry{};
    while (HeapWalk(heaps[i], &entry))
      if (entry.wFlags & PROCESS_HEAP_ENTRY_BUSY) busy += entry.cbData;
    HeapUnlock(heaps[i]);
  }
  return busy;
}

size_t threads_in_this_process() {
  const HANDLE all = CreateToolhelp32Snapshot(TH32CS_SNAPTHREAD, 0);
  if (all == INVALID_HANDLE_VALUE) return 0;
  const DWORD self = GetCurrentProcessId();
  THREADENTRY32 entry{};
  entry.dwSize = sizeof entry;
  size_t n = 0;
  for (BOOL more = Thread32First(all, &entry); more; more = Thread32Next(all, &entry))
    if (entry.th32OwnerProcessID == self) ++n;
  CloseHandle(all);
  return n;
}

std::string why_no_display() {
  // A service runs in a window station nobody sees: windows would open, invisibly.
  USEROBJECTFLAGS flags{};
  HWINSTA station = GetProcessWindowStation();
  if (station && GetUserObjectInformationW(station, UOI_FLAGS, &flags, sizeof flags, nullptr) &&
      !(flags.dwFlags & WSF_VISIBLE))
    return "no display (this process runs in a window station without one, as a service does)";
  return {};
}

}  // namespace fr
