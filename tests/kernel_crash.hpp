// kernel_crash.hpp — what a fault in a scene's kernel ends the render worker with, on each
// system, for the tests that crash it on purpose.
#pragma once

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
#endif

#include <string>

namespace fr::test {

// Whether this is Windows as Wine provides it, whose OpenCL is the Linux PoCL underneath.
inline bool under_wine() {
#ifdef _WIN32
  const HMODULE ntdll = GetModuleHandleW(L"ntdll.dll");
  return ntdll && GetProcAddress(ntdll, "wine_get_version");
#else
  return false;
#endif
}

// The words, '|'-separated: a signal (Linux), an access violation (Windows). Under Wine the kernel
// runs on one of PoCL's own Linux threads, which Wine cannot turn into a Windows exception: the
// process just ends, with status 0.
inline std::string kernel_crash_words() {
  return std::string("crashed (SIGSEGV|crashed (access violation") +
         (under_wine() ? "|the render worker exited with status 0" : "");
}

// Whether `text` says one of them.
inline bool says_kernel_crash(const std::string& text) {
  const std::string words = kernel_crash_words();
  for (size_t at = 0;;) {
    const size_t bar = words.find('|', at);
    if (text.find(words.substr(at, bar - at)) != std::string::npos) return true;
    if (bar == std::string::npos) return false;
    at = bar + 1;
  }
}

}  // namespace fr::test
