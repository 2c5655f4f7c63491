#include "platform/child_process.hpp"

#include "platform/last_error_windows.hpp"

#include <windows.h>

#include <psapi.h>

#include <algorithm>
#include <cstdio>
#include <cwchar>
#include <mutex>
#include <vector>

namespace fr {
namespace {

HANDLE as_handle(NativeHandle h) {
  return reinterpret_cast<HANDLE>(h);
}

std::wstring widen(const std::string& text) {
  if (text.empty()) return {};
  const int n =
      MultiByteToWideChar(CP_UTF8, 0, text.data(), static_cast<int>(text.size()), nullptr, 0);
  std::wstring wide(static_cast<size_t>(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, text.data(), static_cast<int>(text.size()), wide.data(), n);
  return wide;
}

// One argument as the C runtime's command-line parser reads it back: quoted when it has a space,
// a tab or a quote (or is empty); backslashes doubled only where a quote follows them.
void append_argument(std::wstring& line, const std::wstring& arg) {
  if (!line.empty()) line += L' ';
  if (!arg.empty() && arg.find_first_of(L" \t\n\v\"") == std::wstring::npos) {
    line += arg;
    return;
  }
  line += L'"';
  size_t backslashes = 0;
  for (const wchar_t c : arg) {
    if (c == L'\\') {
      ++backslashes;
      continue;
    }
    if (c == L'"') backslashes = backslashes * 2 + 1;
    line.append(backslashes, L'\\');
    backslashes = 0;
    line += c;
  }
  line.append(backslashes * 2, L'\\');
  line += L'"';
}

// Ours less an MPI launcher's variables (MS-MPI's are PMI_* too), as a block for CreateProcessW.
std::vector<wchar_t> child_environment() {
  std::vector<wchar_t> block;
  wchar_t* all = GetEnvironmentStringsW();
  for (const wchar_t* e = all; e && *e; e += std::wcslen(e) + 1) {
    bool launcher = false;
    for (const wchar_t* prefix : {L"OMPI_", L"PMIX_", L"PMI_"})
      launcher = launcher || _wcsnicmp(e, prefix, std::wcslen(prefix)) == 0;
    if (!launcher) block.insert(block.end(), e, e + std::wcslen(e) + 1);
  }
  if (all) FreeEnvironmentStringsW(all);
  if (block.empty()) block.push_back(L'\0');
  block.push_back(L'\0');
  return block;
}

// The job every helper is put in: closing its last handle (fractalis ending, however it ends)
// kills them all.
HANDLE helper_job() {
  static const HANDLE job = [] {
    const HANDLE j = CreateJobObjectW(nullptr, nullptr);
    if (!j) return HANDLE{};
    JOBOBJECT_EXTENDED_LIMIT_INFORMATION limits{};
    limits.BasicLimitInformation.LimitFlags = JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE;
    SetInformationJobObject(j, JobObjectExtendedLimitInformation, &limits, sizeof limits);
    return j;
  }();
  return job;
}

// The NTSTATUS codes a crash ends a process with, and what they mean to a user.
std::string describe_exit_code(DWORD code) {
  switch (code) {
    case 0xC0000005:
      return "crashed (access violation)";
    case 0xC00000FD:
      return "crashed (stack overflow)";
    case 0xC0000094:
      return "crashed (integer division by zero)";
    case 0xC000001D:
      return "crashed (illegal instruction)";
    case 0xC0000409:
      return "crashed (fast fail: a check in the program stopped it)";
    case 0xC0000017:
    case 0xC000012D:
      return "crashed (out of memory)";
    case 0xC000013A:
      return "was stopped (Ctrl-C)";
    case 0xC0000135:
    case 0xC0000139:
      return "could not be started (a DLL it needs is missing)";
    default:
      break;
  }
  if (code >= 0xC0000000) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "%08lX", static_cast<unsigned long>(code));
    return std::string("crashed (exception 0x") + hex + ")";
  }
  return "exited with status " + std::to_string(code);
}

// Handle inheritance is a property of the handle, so two threads starting children at once could
// each hand the other's handles on; the handle list below stops that, and this lock keeps the
// flags' changes from overlapping.
std::mutex inherit_lock;

// How many times a start that failed in Wine's own start-up is tried (ChildProcess::start).
constexpr int kStartAttempts = 4;

}  // namespace

void end_at_once_on_crash() {
  SetUnhandledExceptionFilter([](EXCEPTION_POINTERS* fault) -> LONG {
    TerminateProcess(GetCurrentProcess(), fault->ExceptionRecord->ExceptionCode);
    return EXCEPTION_CONTINUE_SEARCH;  // not reached
  });
}

std::string handle_in_child(size_t index, NativeHandle) {
  // Its value in the child is known only once the child exists (DuplicateHandle, below): the
  // command line names the index, and the child reads the values from its stdin.
  std::string name = "#";  // (not "#" + ...: GCC 12 warns wrongly of overlapping copies there)
  name += std::to_string(index);
  return name;
}

NativeHandle handle_from_argument(const char* text) {
  if (!text || text[0] != '#') return kNoHandle;
  char* end = nullptr;
  const long long index = std::strtoll(text + 1, &end, 10);
  if (*end != '\0' || index < 0) return kNoHandle;
  // The parent wrote one line, "value value ...\n", into our stdin before we ran (start below).
  static const std::vector<long long> given = [] {
    std::vector<long long> values;
    std::string line;
    const HANDLE in = GetStdHandle(STD_INPUT_HANDLE);
    char c = 0;
    DWORD got = 0;
    while (line.size() < 4096 && ReadFile(in, &c, 1, &got, nullptr) && got == 1 && c != '\n')
      line += c;
    const char* at = line.c_str();
    for (char* next = nullptr;; at = next) {
      const long long v = std::strtoll(at, &next, 10);
      if (next == at) break;
      values.push_back(v);
    }
    return values;
  }();
  if (static_cast<size_t>(index) >= given.size() || given[index] <= 0) return kNoHandle;
  return static_cast<NativeHandle>(given[index]);
}

NativeHandle own_stderr() {
  return reinterpret_cast<NativeHandle>(GetStdHandle(STD_ERROR_HANDLE));
}

std::unique_ptr<ChildProcess> ChildProcess::start(const ChildSpec& spec, std::string* error) {
  if (spec.program.empty()) {
    *error = "no program to start";
    return nullptr;
  }
  std::wstring line;
  append_argument(line, spec.program.wstring());
  for (const auto& a : spec.arguments) append_argument(line, widen(a));
  std::vector<wchar_t> environment = child_environment();

  SECURITY_ATTRIBUTES inheritable{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  const HANDLE null_device =
      CreateFileW(L"NUL", GENERIC_READ | GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE,
                  &inheritable, OPEN_EXISTING, 0, nullptr);
  if (null_device == INVALID_HANDLE_VALUE) {
    *error = "cannot open NUL: " + last_error_text();
    return nullptr;
  }
  // A program without a console has no stderr to pass on (GetStdHandle gives null): the null
  // device instead.
  const auto or_null_device = [&](NativeHandle h) {
    return h == kNoHandle || h == 0 ? null_device : as_handle(h);
  };
  const HANDLE out = or_null_device(spec.stdout_to);
  const HANDLE err = or_null_device(spec.stderr_to);
  // The handles it is given are not inherited but duplicated into it while it is suspended, and
  // their values written to its stdin (handle_from_argument): under Wine a file handle a child
  // inherited stays in use until the child exits, even once it has closed it, so that a scene
  // plugin's DLL could not be replaced while its scene host ran.
  HANDLE stdin_read = null_device, stdin_write = nullptr;
  if (!spec.handles.empty() && !CreatePipe(&stdin_read, &stdin_write, &inheritable, 0)) {
    *error = "cannot make a pipe: " + last_error_text();
    CloseHandle(null_device);
    return nullptr;
  }
  if (stdin_write) SetHandleInformation(stdin_write, HANDLE_FLAG_INHERIT, 0);
  // Each handle once: the list refuses duplicates (stdout and stderr may be one pipe).
  std::vector<HANDLE> inherited;
  const auto inherit = [&](HANDLE h) {
    if (std::find(inherited.begin(), inherited.end(), h) == inherited.end()) inherited.push_back(h);
  };
  for (const HANDLE h : {null_device, stdin_read, out, err}) inherit(h);

  SIZE_T attribute_bytes = 0;
  InitializeProcThreadAttributeList(nullptr, 1, 0, &attribute_bytes);
  std::vector<char> attribute_storage(attribute_bytes);
  auto* attributes = reinterpret_cast<LPPROC_THREAD_ATTRIBUTE_LIST>(attribute_storage.data());
  STARTUPINFOEXW startup{};
  startup.StartupInfo.cb = sizeof startup;
  startup.StartupInfo.dwFlags = STARTF_USESTDHANDLES;
  startup.StartupInfo.hStdInput = stdin_read;
  startup.StartupInfo.hStdOutput = out;
  startup.StartupInfo.hStdError = err;
  PROCESS_INFORMATION info{};
  BOOL started = FALSE;
  {
    std::lock_guard<std::mutex> hold(inherit_lock);
    // A helper inherits this error mode: one that crashes ends at once, reported by its exit
    // status, instead of waiting for somebody to close Windows' error reporting dialog, and one
    // that lacks a DLL fails its LoadLibrary without a message box. (Wine ignores it for its
    // crash dialog: scripts/test-windows.sh switches that off in its prefix.)
    SetErrorMode(GetErrorMode() | SEM_FAILCRITICALERRORS | SEM_NOGPFAULTERRORBOX |
                 SEM_NOOPENFILEERRORBOX);
    std::vector<DWORD> flags(inherited.size(), 0);
    for (size_t i = 0; i < inherited.size(); ++i) {
      GetHandleInformation(inherited[i], &flags[i]);
      SetHandleInformation(inherited[i], HANDLE_FLAG_INHERIT, HANDLE_FLAG_INHERIT);
    }
    if (InitializeProcThreadAttributeList(attributes, 1, 0, &attribute_bytes) &&
        UpdateProcThreadAttribute(attributes, 0, PROC_THREAD_ATTRIBUTE_HANDLE_LIST,
                                  inherited.data(), inherited.size() * sizeof(HANDLE), nullptr,
                                  nullptr)) {
      startup.lpAttributeList = attributes;
      // Suspended until it is in the job, so that no code of it runs outside. Under Wine a new
      // process now and then dies while Wine itself starts it, before any code of the program
      // runs, and CreateProcessW says ERROR_INTERNAL_ERROR ("Internal error": it failed
      // platform_test once in CI, not again in hundreds of runs here): nothing of it ran, so
      // it is started again, a few times at most. Any other failure is final at once.
      for (int attempt = 1;; ++attempt) {
        started = CreateProcessW(spec.program.c_str(), line.data(), nullptr, nullptr, TRUE,
                                 CREATE_SUSPENDED | CREATE_UNICODE_ENVIRONMENT |
                                     EXTENDED_STARTUPINFO_PRESENT | CREATE_NO_WINDOW,
                                 environment.data(), nullptr, &startup.StartupInfo, &info);
        if (started || GetLastError() != ERROR_INTERNAL_ERROR || attempt == kStartAttempts) break;
        Sleep(10 * attempt);
      }
      if (!started) *error = last_error_text();
      DeleteProcThreadAttributeList(attributes);
    } else {
      *error = "cannot list the handles to inherit: " + last_error_text();
    }
    for (size_t i = 0; i < inherited.size(); ++i)
      SetHandleInformation(inherited[i], HANDLE_FLAG_INHERIT, flags[i] & HANDLE_FLAG_INHERIT);
  }
  CloseHandle(null_device);
  if (stdin_read != null_device) CloseHandle(stdin_read);
  if (!started) {
    if (stdin_write) CloseHandle(stdin_write);
    return nullptr;
  }
  const HANDLE job = helper_job();
  if (!job || !AssignProcessToJobObject(job, info.hProcess)) {
    *error = "cannot put the child in fractalis's job: " + last_error_text();
    TerminateProcess(info.hProcess, 1);
    if (stdin_write) CloseHandle(stdin_write);
    CloseHandle(info.hThread);
    CloseHandle(info.hProcess);
    return nullptr;
  }
  std::string values;
  for (const NativeHandle h : spec.handles) {
    HANDLE theirs = nullptr;
    if (!DuplicateHandle(GetCurrentProcess(), as_handle(h), info.hProcess, &theirs, 0, FALSE,
                         DUPLICATE_SAME_ACCESS)) {
      *error = "cannot hand a handle to the child: " + last_error_text();
      TerminateProcess(info.hProcess, 1);
      CloseHandle(stdin_write);
      CloseHandle(info.hThread);
      CloseHandle(info.hProcess);
      return nullptr;
    }
    values += std::to_string(reinterpret_cast<intptr_t>(theirs)) + " ";
  }
  if (stdin_write) {
    values += "\n";
    DWORD written = 0;
    WriteFile(stdin_write, values.data(), static_cast<DWORD>(values.size()), &written, nullptr);
    CloseHandle(stdin_write);
  }
  ResumeThread(info.hThread);
  CloseHandle(info.hThread);
  std::unique_ptr<ChildProcess> child(new ChildProcess());
  child->id_ = info.dwProcessId;
  child->process_ = reinterpret_cast<NativeHandle>(info.hProcess);
  return child;
}

ChildProcess::~ChildProcess() {
  if (!ended_) kill();
  if (process_ != kNoHandle) CloseHandle(as_handle(process_));
}

bool ChildProcess::wait(int timeout_ms) {
  if (ended_) return true;
  if (WaitForSingleObject(as_handle(process_), timeout_ms < 0 ? INFINITE : DWORD(timeout_ms)) !=
      WAIT_OBJECT_0)
    return false;
  ended_ = true;
  DWORD code = 0;
  if (!GetExitCodeProcess(as_handle(process_), &code)) {
    how_ = "ended (its status could not be read)";
    return true;
  }
  how_ = describe_exit_code(code);
  if (code < 0xC0000000) exit_status_ = static_cast<int>(code);
  return true;
}

void ChildProcess::kill() {
  if (ended_) return;
  TerminateProcess(as_handle(process_), 0xC000013A);
  wait(-1);
  how_ = "was killed";
  exit_status_ = -1;
}

uint64_t ChildProcess::resident_bytes() const {
  if (ended_) return 0;
  PROCESS_MEMORY_COUNTERS counters{};
  if (!K32GetProcessMemoryInfo(as_handle(process_), &counters, sizeof counters)) return 0;
  return counters.WorkingSetSize;
}

std::string executable_file_name(const std::string& name) {
  return name + ".exe";
}

char path_list_separator() {
  return ';';
}

bool is_executable_file(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

void limit_written_file_size(uint64_t) {
  // Windows has no per-process limit on a file's size; the kernel cache's temporary file is
  // bounded by the build time limit instead.
}

}  // namespace fr
