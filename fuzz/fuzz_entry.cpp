// One libFuzzer program per target: FUZZ_TARGET names the function (fuzz/CMakeLists.txt).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fr::FUZZ_TARGET(data, size);
}
