// cli_run.hpp — running `fractalis` in-process from a test, and the check every usage error
// gets: exit code 2, one line "fractalis: error: ..." naming what was wrong.
#pragma once

#include "cli/cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace fr::test {

struct CliRun {
  int code;
  std::string out, err;
};

inline CliRun run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

inline void expect_usage_error(const std::vector<std::string>& args,
                               const std::string& message_part) {
  const CliRun r = run(args);
  std::string joined;
  for (const auto& a : args) joined += a + " ";
  EXPECT_EQ(r.code, 2) << joined << "\n" << r.err;
  EXPECT_NE(r.err.find(message_part), std::string::npos) << joined << " said: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_EQ(r.err.rfind("fractalis: error: ", 0), 0u) << r.err;
}

}  // namespace fr::test
