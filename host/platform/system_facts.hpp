// system_facts.hpp — the machine a benchmark ran on, what bounds this process's memory, and how
// much of it the allocator has handed out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fr {

struct SystemFacts {
  std::string cpu_model;      // "AMD EPYC 7B13"; "unknown" when the system does not say
  uint64_t memory_bytes = 0;  // physical memory; 0: unknown
  std::string os;             // "Debian GNU/Linux 12 (bookworm), Linux 6.1.0 x86_64"
};
SystemFacts system_facts();

// One bound on how much more memory this process can take: `bytes_left`, and what sets it in
// words ("the address-space limit (ulimit -v)"), with the cap it comes from when it is one.
struct MemoryBound {
  uint64_t bytes_left = 0;
  std::string name;
  uint64_t cap_bytes = 0;  // 0: not a cap (memory the system has free)
};
// Every bound the system applies here (limits, control groups, available memory); none when it
// says nothing.
std::vector<MemoryBound> memory_bounds();

// Bytes of this process's heap in use: handed out by malloc (a plugin's allocations included)
// and not freed yet. The scene host reports it so that a plugin's leak shows (scene_wire.hpp's
// HostStats). Linux: malloc's own count (AddressSanitizer's under that sanitizer); Windows: the
// busy blocks of the process's heaps.
uint64_t heap_bytes_in_use();

// Threads this process runs now. The scene host compares it with the count it started with, to
// see a plugin's threads that outlive it (`fractalis check`'s unload).
size_t threads_in_this_process();

// Empty when this process can open windows; otherwise why not, for the message. Linux: an X11 or
// Wayland display named in the environment; Windows: a visible window station (not a service).
std::string why_no_display();

}  // namespace fr
