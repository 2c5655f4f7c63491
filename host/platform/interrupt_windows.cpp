#include "platform/interrupt.hpp"

#include <windows.h>

#include <atomic>

namespace fr {
namespace {

std::atomic<bool> g_catching{false};
std::atomic<bool> g_interrupted{false};
std::atomic<void (*)()> g_last_words{nullptr};

// Runs on a thread the system starts for the event. TRUE: handled; FALSE: the next handler (in
// the end the default one, which ends the process).
BOOL WINAPI on_console_event(DWORD event) {
  if (g_catching && (event == CTRL_C_EVENT || event == CTRL_BREAK_EVENT)) {
    g_interrupted = true;
    return TRUE;
  }
  if (void (*last_words)() = g_last_words.load()) last_words();
  return FALSE;
}

void install_once() {
  static const bool installed = SetConsoleCtrlHandler(on_console_event, TRUE) != 0;
  (void)installed;
}

}  // namespace

InterruptCatcher::InterruptCatcher() {
  install_once();
  g_interrupted = false;
  g_catching = true;
}

InterruptCatcher::~InterruptCatcher() {
  g_catching = false;
}

bool InterruptCatcher::interrupted() {
  return g_interrupted;
}

void on_termination_request(void (*last_words)()) {
  g_last_words = last_words;
  install_once();
}

}  // namespace fr
