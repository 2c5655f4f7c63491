#include "io/check.hpp"

#include <cstdio>
#include <cstdlib>

namespace fr {

void check_failed(const char* condition, const char* why, const char* file, int line) {
  std::fprintf(stderr, "fractalis: internal error at %s:%d: %s (%s is false); please report it\n",
               file, line, why, condition);
  std::fflush(stderr);
  std::abort();
}

}  // namespace fr
