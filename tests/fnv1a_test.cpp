// io/fnv1a.hpp against the published FNV-1a 64-bit test vectors, and hashing in pieces.
#include "io/fnv1a.hpp"

#include <gtest/gtest.h>

namespace fr {
namespace {

TEST(Fnv1a, PublishedVectors) {
  EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a("foobar"), 0x85944171f73967e8ull);
  EXPECT_EQ(hex16(fnv1a("a")), "af63dc4c8601ec8c");
  static_assert(fnv1a("") == kFnv1aOffset);
}

TEST(Fnv1a, PiecesHashAsTheirConcatenation) {
  EXPECT_EQ(fnv1a("bar", fnv1a("foo")), fnv1a("foobar"));
}

}  // namespace
}  // namespace fr
