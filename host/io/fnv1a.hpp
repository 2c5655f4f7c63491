// fnv1a.hpp — 64-bit FNV-1a: a hash that is the same across runs, machines and builds (std::hash
// is none of these), for cache keys and content digests. Not for security. (Its four copies before
// this file all started from 1469598103934665603, the offset basis with its last digit lost:
// tests/fnv1a_test.cpp checks the published vectors.)
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace fr {

inline constexpr uint64_t kFnv1aOffset = 14695981039346656037ull;

// The hash of `data`, continuing from `h` (so that pieces hash as their concatenation would).
constexpr uint64_t fnv1a(std::string_view data, uint64_t h = kFnv1aOffset) {
  for (const unsigned char c : data) h = (h ^ c) * 1099511628211ull;
  return h;
}

// Sixteen lowercase hex digits.
inline std::string hex16(uint64_t h) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace fr
