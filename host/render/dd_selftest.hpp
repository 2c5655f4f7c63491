// dd_selftest.hpp — does a device keep double-double arithmetic's error terms?
//
// Double-double (kernels/de/dd.cl) rests on two exact transformations, TwoSum and TwoProd; a
// compiler that reassociates floating point (fast or unsafe math) or a device that flushes or
// rounds otherwise silently zeroes their error terms, and a deep view would come out as double's
// noise with nothing said. So before using pairs on a device, this runs both on it over inputs
// chosen to have error terms (every binade gap a view needs, signs, subnormal results, ties) and
// checks the results on the host in __float128, which holds each exact sum and product: s + e
// must equal a + b, p + e must equal a b, and s, p must be the rounded results.
#pragma once

#include "render/cl_runtime.hpp"

#include <string>

namespace fr {

struct DdSelftest {
  bool exact = false;
  int cases = 0;       // pairs checked
  std::string failed;  // the first case that failed, or why the test could not run
};

// Runs the test on `runtime`'s device. `build_options` replaces the kernel's (tests pass
// "-cl-fast-relaxed-math" to see that a fast-math build fails it). A device without double
// precision is not exact (failed says so).
DdSelftest dd_selftest(ClRuntime& runtime, const std::string& build_options = "-cl-std=CL1.2 -w");

}  // namespace fr
