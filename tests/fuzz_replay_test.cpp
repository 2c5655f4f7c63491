// Every input kept for the fuzz targets (fuzz/corpus: seeds and what the fuzzer found worth
// keeping; fuzz/regressions: inputs that once crashed a target) runs through its target here, in
// every build: a crash that was fixed stays fixed, under the sanitizers too.
#include "fuzz_targets.hpp"
#include "test_support.hpp"

#include <fstream>
#include <sstream>

namespace fr {
namespace {

TEST(FuzzReplay, EveryKeptInputRunsCleanly) {
  for (const FuzzTarget& target : kFuzzTargets) {
    size_t inputs = 0;
    for (const char* kind : {"corpus", "regressions"}) {
      const auto dir = std::filesystem::path(SOURCE_DIR) / "fuzz" / kind / target.name;
      if (!std::filesystem::is_directory(dir)) continue;
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (!entry.is_regular_file() || entry.path().filename() == ".gitkeep") continue;
        SCOPED_TRACE(entry.path().string());
        std::ifstream in(entry.path(), std::ios::binary);
        std::stringstream bytes;
        bytes << in.rdbuf();
        const std::string data = bytes.str();
        EXPECT_EQ(target.run(reinterpret_cast<const uint8_t*>(data.data()), data.size()), 0);
        ++inputs;
      }
    }
    EXPECT_GT(inputs, 0u) << target.name << " has no inputs to replay";
  }
}

}  // namespace
}  // namespace fr
