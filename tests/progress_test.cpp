// The one progress display (cli/progress.hpp) of render, animate and sweep: a bar redrawn in
// place on a terminal, at most about a hundred plain lines otherwise, and always the last step.
#include "cli/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace fr {
namespace {

TEST(Progress, TerminalBarIsRedrawnInPlaceWithItsDetail) {
  std::ostringstream err;
  Progress p(err, "step", 10, 0, true);
  p.update(3, "measuring max_steps=80");
  const std::string bar = err.str();
  EXPECT_EQ(bar.rfind("\r[#########.....................] step 3/10: measuring max_steps=80, ", 0),
            0u)
      << bar;
  EXPECT_NE(bar.find(" s left\033[K"), std::string::npos) << "cleared to the end of the line";
  EXPECT_EQ(bar.find('\n'), std::string::npos);
  p.update(12);  // past the end: a full bar, not a crash
  EXPECT_NE(err.str().find("[##############################] step 12/10"), std::string::npos);
  p.finish();
  p.finish();
  const std::string all = err.str();
  EXPECT_EQ(std::count(all.begin(), all.end(), '\n'), 1) << "one line end, once";
}

TEST(Progress, PlainLinesAreFewAndEndWithTheLastStep) {
  std::ostringstream err;
  Progress p(err, "frame", 1000, 0, false);
  for (int i = 1; i <= 1000; ++i) p.update(i);
  p.finish();
  const std::string text = err.str();
  const auto lines = std::count(text.begin(), text.end(), '\n');
  EXPECT_GE(lines, 10);
  EXPECT_LE(lines, 101);
  EXPECT_EQ(text.find('\r'), std::string::npos) << "no carriage returns in a log";
  const size_t last = text.rfind("frame ", text.size() - 2);
  EXPECT_EQ(text.substr(last, 15), "frame 1000/1000");
}

}  // namespace
}  // namespace fr
