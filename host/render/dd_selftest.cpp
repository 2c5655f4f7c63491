#include "render/dd_selftest.hpp"

#include "render/kernel_sources.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace fr {
namespace {

// Pairs whose sum and product have error terms: a tiny addend below the other's last bit, sums
// that cancel, thirds and tenths (no finite binary expansion), products of 53-bit mantissas,
// both signs, and magnitudes from 2^-1000 to 2^1000 (products that stay normal).
std::vector<double> selftest_pairs() {
  std::vector<double> pairs;
  const double values[] = {1.0,
                           1.0 / 3.0,
                           0.1,
                           -2.0 / 7.0,
                           3.141592653589793,
                           1.0 + std::ldexp(1.0, -52),
                           std::ldexp(1.0, -60),
                           -std::ldexp(1.0, -80),
                           1e-20,
                           123456789.123456789,
                           std::ldexp(0.75, 300),
                           -std::ldexp(0.9, -300),
                           std::nextafter(1.0, 2.0),
                           std::nextafter(-1.0, -2.0)};
  for (double a : values)
    for (double b : values) {
      pairs.push_back(a);
      pairs.push_back(b);
    }
  return pairs;
}

std::string describe(const char* what, double a, double b, double hi, double lo) {
  char text[256];
  std::snprintf(text, sizeof text, "%s of %.17g and %.17g gave %.17g + %.17g, not exact", what, a,
                b, hi, lo);
  return text;
}

}  // namespace

DdSelftest dd_selftest(ClRuntime& runtime, const std::string& build_options) {
  DdSelftest result;
  if (!runtime.device().has_fp64) {
    result.failed = "the device has no double precision (cl_khr_fp64)";
    return result;
  }
  std::ostringstream source;
  source << "#define FR_LANES 1\n#define FR_DOUBLE 1\n"
         << kernel_source("prelude.cl") << "\n"
         << kernel_source("de/dd.cl") << "\n"
         << kernel_source("dd_selftest.cl") << "\n";
  const std::vector<double> pairs = selftest_pairs();
  const int count = static_cast<int>(pairs.size() / 2);
  std::vector<double> out(4 * pairs.size() / 2);
  try {
    cl_kernel kernel = runtime.kernel(
        runtime.program(source.str(), build_options, "the double-double self-test"),
        "fr_dd_selftest");
    cl_int err = CL_SUCCESS;
    ClBufferHandle in(clCreateBuffer(runtime.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                     pairs.size() * sizeof(double),
                                     const_cast<double*>(pairs.data()), &err));
    cl_check(err, "clCreateBuffer", "self-test pairs");
    ClBufferHandle results(clCreateBuffer(runtime.context(), CL_MEM_WRITE_ONLY,
                                          out.size() * sizeof(double), nullptr, &err));
    cl_check(err, "clCreateBuffer", "self-test results");
    const cl_mem in_mem = in.get(), out_mem = results.get();
    cl_check(clSetKernelArg(kernel, 0, sizeof in_mem, &in_mem), "clSetKernelArg");
    cl_check(clSetKernelArg(kernel, 1, sizeof out_mem, &out_mem), "clSetKernelArg");
    cl_check(clSetKernelArg(kernel, 2, sizeof count, &count), "clSetKernelArg");
    const size_t global = static_cast<size_t>(count);
    cl_check(clEnqueueNDRangeKernel(runtime.queue(), kernel, 1, nullptr, &global, nullptr, 0,
                                    nullptr, nullptr),
             "clEnqueueNDRangeKernel", "the double-double self-test");
    cl_check(clEnqueueReadBuffer(runtime.queue(), out_mem, CL_TRUE, 0, out.size() * sizeof(double),
                                 out.data(), 0, nullptr, nullptr),
             "clEnqueueReadBuffer", "the double-double self-test");
  } catch (const std::exception& e) {
    result.failed = e.what();
    return result;
  }
  // __float128 (113 bits) holds a + b exactly when the exponents differ by at most 59; further
  // apart the smaller is below half an ulp of the larger, so s must be the larger and e the
  // smaller itself. It holds every product of two doubles (106 bits).
  for (int i = 0; i < count; ++i) {
    const double a = pairs[2 * i], b = pairs[2 * i + 1];
    const double s = out[4 * i], se = out[4 * i + 1], p = out[4 * i + 2], pe = out[4 * i + 3];
    ++result.cases;
    int exponent_a = 0, exponent_b = 0;
    std::frexp(a, &exponent_a);
    std::frexp(b, &exponent_b);
    const bool near = std::abs(exponent_a - exponent_b) <= 59;
    const double larger = std::abs(a) >= std::abs(b) ? a : b, smaller = larger == a ? b : a;
    const bool sum_exact =
        s == a + b && (near ? (__float128)s + se == (__float128)a + b : s == larger && se == smaller);
    const bool product_exact = p == a * b && (__float128)p + pe == (__float128)a * b;
    if (!sum_exact) {
      result.failed = describe("TwoSum", a, b, s, se);
      return result;
    }
    if (!product_exact) {
      result.failed = describe("TwoProd", a, b, p, pe);
      return result;
    }
  }
  result.exact = true;
  return result;
}

}  // namespace fr
