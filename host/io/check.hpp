// check.hpp — FR_CHECK, the one way the host states an invariant of its own code.
//
// Bad input gets a clear error through each layer's error channel (CONVENTIONS.md); a broken
// invariant is a bug in fractalis, and carrying on with a made-up value ("the first name" for an
// enum value no table lists) hides it. FR_CHECK prints the file, line and condition and aborts,
// in every build type (the checks guard cheap conditions off the per-pixel paths).
#pragma once

namespace fr {

[[noreturn]] void check_failed(const char* condition, const char* why, const char* file, int line);

}  // namespace fr

// FR_CHECK(condition, "what it means"): usable in constexpr functions (the failure path is
// never constant-evaluated).
#define FR_CHECK(condition, why) \
  ((condition) ? void(0) : ::fr::check_failed(#condition, why, __FILE__, __LINE__))
