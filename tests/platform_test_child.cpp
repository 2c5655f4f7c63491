// The child that tests/platform_test.cpp starts through platform/child_process.hpp, on Linux
// and under Wine: each first argument is one behaviour the test then checks from outside.
#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "platform/user_folders.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

// The sanitizer build links AddressSanitizer's runtime into this program too: "crash" must stay a
// crash, not become its report and exit status 1.
extern "C" const char* __asan_default_options() {
  return "handle_segv=0:detect_leaks=0";
}

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  const std::string mode = argv[1];
  if (mode == "echo" && argc == 3) {  // sends back what arrives on the channel until it closes
    fr::Channel channel(fr::handle_from_argument(argv[2]));
    if (!channel.is_open()) return 3;
    char buffer[4096];
    for (;;) {
      size_t got = 0;
      const fr::ChannelStatus s = channel.read_some(buffer, sizeof buffer, -1, &got);
      if (s == fr::ChannelStatus::Closed) return 0;
      if (s != fr::ChannelStatus::Ok) return 4;
      if (!channel.write_all(buffer, got)) return 5;
    }
  }
  if (mode == "print" && argc == 3) {
    std::printf("%s\n", argv[2]);
    return 0;
  }
  if (mode == "env" && argc >= 3) {  // prints NAME=value of each variable named, or NAME unset
    for (int i = 2; i < argc; ++i) {
      const char* value = std::getenv(argv[i]);
      std::printf("%s%s%s\n", argv[i], value ? "=" : " unset", value ? value : "");
    }
    return 0;
  }
  if (mode == "exit" && argc == 3) return std::atoi(argv[2]);
  if (mode == "crash") {
    volatile int* nowhere = nullptr;
    *nowhere = 1;
    return 0;
  }
  if (mode == "hang") {
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
  }
  if (mode == "spawn-hang" && argc == 3) {  // starts a child of its own that holds the channel
    fr::Channel channel(fr::handle_from_argument(argv[2]));
    fr::ChildSpec spec;
    spec.program = fr::executable_path();
    spec.arguments = {"hang"};
    spec.handles = {channel.handle()};
    std::string error;
    auto grandchild = fr::ChildProcess::start(spec, &error);
    if (!grandchild) return 7;
    const char ready = 'r';
    if (!channel.write_all(&ready, 1)) return 5;
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
  }
  if (mode == "memory" && argc == 4) {  // holds MIB mebibytes, says so on the channel, waits
    fr::Channel channel(fr::handle_from_argument(argv[3]));
    std::vector<char> held(static_cast<size_t>(std::atoi(argv[2])) << 20);
    for (size_t i = 0; i < held.size(); i += 4096) held[i] = static_cast<char>(i >> 12);
    const char ready = 'r';
    if (!channel.write_all(&ready, 1)) return 5;
    char ignored;
    size_t got = 0;
    channel.read_some(&ignored, 1, -1, &got);  // until the test closes its end
    return held[4096] == 1 ? 0 : 6;
  }
  return 2;
}
