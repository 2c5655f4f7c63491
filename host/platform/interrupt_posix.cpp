#include "platform/interrupt.hpp"

#include <signal.h>

#include <atomic>

namespace fr {
namespace {

std::atomic<bool> g_interrupted{false};
std::atomic<void (*)()> g_last_words{nullptr};
struct sigaction g_old_int, g_old_term;

extern "C" void set_interrupted(int) {
  g_interrupted = true;
}

extern "C" void say_last_words_and_end(int sig) {
  if (void (*last_words)() = g_last_words.load()) last_words();
  signal(sig, SIG_DFL);
  raise(sig);
}

}  // namespace

InterruptCatcher::InterruptCatcher() {
  g_interrupted = false;
  struct sigaction sa {};
  sa.sa_handler = set_interrupted;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptCatcher::~InterruptCatcher() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
}

bool InterruptCatcher::interrupted() {
  return g_interrupted;
}

void on_termination_request(void (*last_words)()) {
  g_last_words = last_words;
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;  // e.g. nohup
    struct sigaction sa {};
    sa.sa_handler = say_last_words_and_end;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace fr
