// Double-double arithmetic on the device (kernels/de/dd.cl) and the Mandelbox in it
// (kernels/de/mandelbox_dd.cl), against a host reference in __float128 (113 bits) that shares no
// code with the kernels: the self-test passes here and fails for a fast-math build; each
// operation's relative error is within a few 2^-106; and at points 1e-22 from the Mandelbox's
// surface, where double cannot even hold the point, the pair DE agrees with the reference within
// a thousandth of such a pixel while double cannot tell the points apart (why pairs are needed).
#include "float128_reference.hpp"
#include "render/dd_selftest.hpp"
#include "render/kernel_sources.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fr {
namespace {
using test::BoxReference;
using test::quad;
using test::quad_abs;
using test::quad_sqrt;
using test::split;
using test::SpongeReference;

// A program of the library's files for a kernel written here: the files' "#include "fr/..."
// lines dropped (the files are given in dependency order instead).
std::string program(int lanes, const std::vector<std::string>& library, const std::string& kernel) {
  std::ostringstream source;
  source << "#define FR_LANES " << lanes << "\n#define FR_DOUBLE 1\n"
         << kernel_source("prelude.cl") << "\n";
  for (const std::string& file : library) {
    std::istringstream lines{std::string(kernel_source(file))};
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("#include \"fr/", 0) != 0) source << line << "\n";
  }
  source << "#if FR_LANES == 1\n#define LOAD(i, p) (p)[i]\n#define STORE(v, i, p) (p)[i] = (v)\n"
            "#else\n#define LOAD(i, p) FR_CAT(vload, FR_LANES)(i, p)\n"
            "#define STORE(v, i, p) FR_CAT(vstore, FR_LANES)(v, i, p)\n#endif\n"
         << kernel;
  return source.str();
}

// Runs kernel `name` over `count` values (a multiple of `lanes`, one LOAD a work-item): its
// arguments are `inputs` (arrays of `count` doubles each), then `out` (`outputs` x `count`
// doubles), then `scalars` (doubles), in that order.
std::vector<double> run(ClRuntime& runtime, const std::string& source, const char* name,
                        int lanes, const std::vector<std::vector<double>>& inputs,
                        const std::vector<double>& scalars, size_t outputs = 1) {
  const size_t count = inputs.front().size();
  cl_kernel kernel = runtime.kernel(runtime.program(source, "-cl-std=CL1.2 -w", name), name);
  std::vector<ClBufferHandle> buffers;
  cl_uint arg = 0;
  cl_int err = CL_SUCCESS;
  for (const auto& in : inputs) {
    buffers.emplace_back(clCreateBuffer(runtime.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                        count * sizeof(double), const_cast<double*>(in.data()),
                                        &err));
    cl_check(err, "clCreateBuffer", name);
    const cl_mem m = buffers.back().get();
    cl_check(clSetKernelArg(kernel, arg++, sizeof m, &m), "clSetKernelArg");
  }
  ClBufferHandle out(clCreateBuffer(runtime.context(), CL_MEM_WRITE_ONLY,
                                    outputs * count * sizeof(double), nullptr, &err));
  cl_check(err, "clCreateBuffer", name);
  const cl_mem out_mem = out.get();
  cl_check(clSetKernelArg(kernel, arg++, sizeof out_mem, &out_mem), "clSetKernelArg");
  for (double s : scalars) cl_check(clSetKernelArg(kernel, arg++, sizeof s, &s), "clSetKernelArg");
  const size_t global = count / static_cast<size_t>(lanes);
  cl_check(clEnqueueNDRangeKernel(runtime.queue(), kernel, 1, nullptr, &global, nullptr, 0,
                                  nullptr, nullptr),
           "clEnqueueNDRangeKernel", name);
  std::vector<double> result(outputs * count);
  cl_check(clEnqueueReadBuffer(runtime.queue(), out_mem, CL_TRUE, 0, result.size() * sizeof(double),
                               result.data(), 0, nullptr, nullptr),
           "clEnqueueReadBuffer", name);
  return result;
}

bool has_fp64() {
  return test::runtime().device().has_fp64;
}

TEST(DoubleDouble, SelfTestPassesHereAndFailsForAFastMathBuild) {
  if (!has_fp64()) GTEST_SKIP() << "the device has no double precision";
  const DdSelftest plain = dd_selftest(test::runtime());
  EXPECT_TRUE(plain.exact) << plain.failed;
  EXPECT_GE(plain.cases, 100);
  // The mutation the self-test exists for: fast math lets the compiler reassociate TwoSum's
  // (a - (s - v)) to 0.
  const DdSelftest fast = dd_selftest(test::runtime(), "-cl-std=CL1.2 -cl-fast-relaxed-math -w");
  EXPECT_FALSE(fast.exact) << "a fast-math build kept every error term";
  EXPECT_NE(fast.failed.find("not exact"), std::string::npos) << fast.failed;
}

// Each operation on pairs against __float128, over values of many magnitudes and both signs: the
// relative error within 8 x 2^-106 (QD's bounds are 2 to 4 ulps of the pair), at 1 and 16 lanes.
// (Op 4: a double over a pair, dd_div_d_by, the Mandelbox's sphere fold.)
TEST(DoubleDouble, OperationsAgreeWithFloat128) {
  if (!has_fp64()) GTEST_SKIP() << "the device has no double precision";
  const std::string kernel = R"(
__kernel void ops(__global const double* ahi, __global const double* alo,
                  __global const double* bhi, __global const double* blo, __global double* out,
                  double op) {
  const int i = get_global_id(0);
  const dd_t a = dd_make(LOAD(i, ahi), LOAD(i, alo)), b = dd_make(LOAD(i, bhi), LOAD(i, blo));
  dd_t r;
  if (op == 0) r = dd_add(a, b);
  else if (op == 1) r = dd_mul(a, b);
  else if (op == 2) r = dd_div(a, b);
  else if (op == 3) r = dd_sqrt(dd_abs(a));
  else r = dd_div_d_by(a.hi, b);
  /* hi in the first half of out, lo in the second */
  STORE(r.hi, i, out);
  STORE(r.lo, i, out + get_global_size(0) * FR_LANES);
}
)";
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-40, 40);
  const int n = 512;
  std::vector<quad> a(n), b(n);
  std::vector<double> ahi(n), alo(n), bhi(n), blo(n);
  for (int i = 0; i < n; ++i) {
    a[i] = static_cast<quad>(std::ldexp(unit(random), exponent(random))) +
           static_cast<quad>(std::ldexp(unit(random), exponent(random) - 60));
    b[i] = static_cast<quad>(std::ldexp(unit(random), exponent(random))) +
           static_cast<quad>(std::ldexp(unit(random), exponent(random) - 60));
    if (b[i] == 0) b[i] = 1;
    split(a[i], &ahi[i], &alo[i]);
    split(b[i], &bhi[i], &blo[i]);
    a[i] = static_cast<quad>(ahi[i]) + alo[i];  // exactly the pair the device gets
    b[i] = static_cast<quad>(bhi[i]) + blo[i];
  }
  for (int lanes : {1, 16}) {
    const std::string source = program(lanes, {"de/dd.cl"}, kernel);
    for (int op = 0; op < 5; ++op) {
      SCOPED_TRACE("lanes " + std::to_string(lanes) + ", op " + std::to_string(op));
      const auto out =
          run(test::runtime(), source, "ops", lanes, {ahi, alo, bhi, blo}, {double(op)}, 2);
      double worst = 0;
      for (int i = 0; i < n; ++i) {
        const quad expected = op == 0   ? a[i] + b[i]
                              : op == 1 ? a[i] * b[i]
                              : op == 2 ? a[i] / b[i]
                              : op == 3 ? quad_sqrt(quad_abs(a[i]))
                                        : static_cast<quad>(ahi[i]) / b[i];
        const quad got = static_cast<quad>(out[i]) + out[n + i];
        // (A sum that cancels is exact to the pair's absolute precision, not its relative one.)
        const quad scale = op == 0 ? quad_abs(a[i]) + quad_abs(b[i]) : quad_abs(expected);
        if (scale == 0) continue;
        worst = std::max(worst, static_cast<double>(quad_abs(got - expected) / scale));
      }
      EXPECT_LE(worst, 8 * std::ldexp(1.0, -106));
    }
  }
}

// Test points 1e-22 to 1.6e-21 outside a shape's surface, 16 along each of four rays: sphere
// tracing in __float128 from `start` until the reference estimate is below 1e-24, then back.
struct DeepPoints {
  std::vector<double> xhi, xlo, yhi, ylo, zhi, zlo;  // as the device gets them
  std::vector<quad> reference;                       // the reference estimate there
};

template <class Reference>
DeepPoints deep_points(const Reference& shape, const double start[3], const double aims[4][3]) {
  DeepPoints out;
  for (int ray = 0; ray < 4; ++ray) {
    const double d[3] = {aims[ray][0] - start[0], aims[ray][1] - start[1], aims[ray][2] - start[2]};
    const quad length = quad_sqrt(quad(d[0]) * d[0] + quad(d[1]) * d[1] + quad(d[2]) * d[2]);
    const quad dir[3] = {d[0] / length, d[1] / length, d[2] / length};
    quad t = 0, de = 1;
    quad p[3];
    int steps = 0;
    for (; steps < 5000 && de > 1e-24; ++steps) {
      for (int c = 0; c < 3; ++c) p[c] = start[c] + t * dir[c];
      de = shape.de(p);
      t += de;
      if (t > 30) break;
    }
    EXPECT_LT(t, 30) << "the ray missed";
    EXPECT_LE(de, 1e-24) << "the tracing stalled at " << static_cast<double>(de) << " after "
                         << steps << " steps";
    for (int k = 1; k <= 16; ++k) {
      const quad back = t - quad(k) * 1e-22;
      double v[6];
      for (int c = 0; c < 3; ++c) split(start[c] + back * dir[c], &v[2 * c], &v[2 * c + 1]);
      out.xhi.push_back(v[0]);
      out.xlo.push_back(v[1]);
      out.yhi.push_back(v[2]);
      out.ylo.push_back(v[3]);
      out.zhi.push_back(v[4]);
      out.zlo.push_back(v[5]);
      const quad q[3] = {quad(v[0]) + v[1], quad(v[2]) + v[3], quad(v[4]) + v[5]};
      out.reference.push_back(shape.de(q));
      EXPECT_TRUE(out.reference.back() >= 0 && out.reference.back() < 1e-20)
          << "a point " << static_cast<double>(out.reference.back()) << " from the surface";
    }
  }
  return out;
}

// The pair DE (kernel `pairs`) against the reference at the deep points, switching to double at
// a pixel of 1e-22 (within a thousandth of it) and in pairs throughout (within 1e-28); the double
// DE (kernel `doubles`) at the rounded points, which cannot tell a ray's 16 points apart.
void check_deep(const DeepPoints& points, const std::vector<std::string>& library,
                const std::string& kernels, double iterations) {
  const size_t n = points.reference.size();  // 64: a multiple of 16
  const std::vector<std::vector<double>> in = {points.xhi, points.xlo, points.yhi,
                                               points.ylo, points.zhi, points.zlo};
  for (int lanes : {1, 16}) {
    const std::string source = program(lanes, library, kernels);
    for (double pixel : {1e-22, 0.0}) {
      SCOPED_TRACE("lanes " + std::to_string(lanes) + ", pixel " + std::to_string(pixel));
      const auto got = run(test::runtime(), source, "pairs", lanes, in, {iterations, pixel});
      double worst = 0;
      for (size_t i = 0; i < n; ++i)
        worst = std::max(worst, static_cast<double>(quad_abs(quad(got[i]) - points.reference[i])));
      EXPECT_LE(worst, pixel > 0 ? 1e-3 * pixel : 1e-28);
    }
    // The 16 points of a ray, 1e-22 apart, round to one or two doubles (an ulp there is about
    // 2e-16): at most two answers where the estimate takes 16 values that differ by more than
    // the pairs' error, so a depth map there is flat noise.
    const auto plain = run(test::runtime(), source, "doubles", lanes, in, {iterations, 0.0});
    for (size_t ray = 0; ray < n / 16; ++ray) {
      std::vector<double> answers;
      quad lowest = points.reference[16 * ray], highest = lowest;
      for (size_t k = 0; k < 16; ++k) {
        const size_t i = 16 * ray + k;
        if (std::find(answers.begin(), answers.end(), plain[i]) == answers.end())
          answers.push_back(plain[i]);
        lowest = std::min(lowest, points.reference[i]);
        highest = std::max(highest, points.reference[i]);
      }
      EXPECT_LE(answers.size(), 2u) << "ray " << ray << ": double told the points apart";
      EXPECT_GT(static_cast<double>(highest - lowest), 1e-25)
          << "ray " << ray << ": the estimate does not change over 1.6e-21";
    }
  }
}

// The kernels' arguments: the six arrays of pairs, the output, iterations and pixel.
const char* const kDeepArguments =
    "__global const double* xhi, __global const double* xlo, __global const double* yhi, "
    "__global const double* ylo, __global const double* zhi, __global const double* zlo, "
    "__global double* out, double iterations, double pixel";
const char* const kDeepPoint =
    "  const int i = get_global_id(0);\n"
    "  const dd3_t p = dd3_make(dd_make(LOAD(i, xhi), LOAD(i, xlo)), dd_make(LOAD(i, yhi), "
    "LOAD(i, ylo)), dd_make(LOAD(i, zhi), LOAD(i, zlo)));\n"
    "  const vec3_t rounded = v3(LOAD(i, xhi), LOAD(i, yhi), LOAD(i, zhi));\n"
    "  real_t trap;\n";

TEST(DoubleDouble, MandelboxAtPointsNearTheSurfaceAgreesWithFloat128) {
  if (!has_fp64()) GTEST_SKIP() << "the device has no double precision";
  const BoxReference box;
  const double start[3] = {5, 4, 5};
  const double aims[4][3] = {{2, 1.5, 1.9}, {3.5, -0.5, 3.5}, {1, 3.6, 2.1}, {2.75, 0.5, 2.25}};
  const DeepPoints points = deep_points(box, start, aims);
  if (HasFailure()) return;
  const std::string kernels =
      std::string("__kernel void pairs(") + kDeepArguments + ") {\n" + kDeepPoint +
      "  STORE(de_mandelbox_dd(p, (int)iterations, 2.0, 0.5, 1.0, 1.0, (real_t)pixel), i, out);\n"
      "}\n__kernel void doubles(" + kDeepArguments + ") {\n" + kDeepPoint +
      "  STORE(de_mandelbox(rounded, (int)iterations, 2.0, 0.5, 1.0, 1.0, &trap), i, out);\n}\n";
  check_deep(points,
             {"de/primitives.cl", "de/operators.cl", "de/folds.cl", "de/mandelbox.cl", "de/kifs.cl",
              "de/dd.cl", "de/dd_folds.cl", "de/mandelbox_dd.cl"},
             kernels, box.iterations);
}

TEST(DoubleDouble, MengerAtPointsNearTheSurfaceAgreesWithFloat128) {
  if (!has_fp64()) GTEST_SKIP() << "the device has no double precision";
  const SpongeReference sponge;
  const double start[3] = {1.6, 1.5, 1.7};
  const double aims[4][3] = {{0.3, 0.2, 0.1}, {0.1, -0.2, 0.3}, {-0.2, 0.1, 0.25}, {0.25, 0.3, -0.1}};
  const DeepPoints points = deep_points(sponge, start, aims);
  if (HasFailure()) return;
  const std::string kernels =
      std::string("__kernel void pairs(") + kDeepArguments + ") {\n" + kDeepPoint +
      "  STORE(de_menger_dd(p, (int)iterations, 3.0, v3s(1, 1, 1), 0.0, (real_t)pixel), i, out);\n"
      "}\n__kernel void doubles(" + kDeepArguments + ") {\n" + kDeepPoint +
      "  STORE(de_menger(rounded, (int)iterations, 3.0, v3s(1, 1, 1), 0.0, &trap), i, out);\n}\n";
  check_deep(points,
             {"de/primitives.cl", "de/operators.cl", "de/folds.cl", "de/menger.cl", "de/kifs.cl",
              "de/dd.cl", "de/dd_folds.cl", "de/menger_dd.cl"},
             kernels, sponge.iterations);
}

}  // namespace
}  // namespace fr
namespace fr {
namespace {

// The Mandelbulb in pairs (kernels/de/mandelbulb_dd.cl) at 8 iterations, 16 points 2.2e-21
// apart and 1.9e-20 to 2.7e-20 off the level set r_8 = 1 that is its surface there (the point
// `fractalis check` marched to), against the reference through the angles: within a thousandth
// of the points' spacing at 1 and 16 lanes. There |z| ends within a few ulps of 1, so the
// estimate must take it from the pairs; a scalar condition once ORed into a lane mask made the
// 16-lane kernel take the rounded |z| instead (steps of 5e-21, a quarter of the values).
TEST(DoubleDouble, MandelbulbOfFewIterationsAgreesWithFloat128) {
  if (!has_fp64()) GTEST_SKIP() << "the device has no double precision";
  const double origin[6] = {-0.002139145301554984, -4.9569920699088645e-20,
                            -0.49464381549985686,  8.4863053987234765e-19,
                            -0.7461580250734352,   2.3017967506556419e-17};
  const double dir[3] = {0.94972814643046499, 0.30105393971814443, 0.085924229748871928};
  const double across[3] = {dir[1] - dir[2], dir[2] - dir[0], dir[0] - dir[1]};
  const double across_length =
      std::sqrt(across[0] * across[0] + across[1] * across[1] + across[2] * across[2]);
  const double spacing = 2.2e-21;
  test::BulbReference bulb;
  bulb.iterations = 8;
  std::vector<double> xh, xl, yh, yl, zh, zl;
  std::vector<quad> reference;
  for (int k = 0; k < 16; ++k) {
    quad q[3];
    for (int c = 0; c < 3; ++c)
      q[c] = quad(origin[2 * c]) + origin[2 * c + 1] +
             (-dir[c] * (k + 1) + across[c] / across_length * k) * spacing;
    double h = 0, l = 0;
    split(q[0], &h, &l);
    xh.push_back(h);
    xl.push_back(l);
    split(q[1], &h, &l);
    yh.push_back(h);
    yl.push_back(l);
    split(q[2], &h, &l);
    zh.push_back(h);
    zl.push_back(l);
    const quad at[3] = {quad(xh.back()) + xl.back(), quad(yh.back()) + yl.back(),
                        quad(zh.back()) + zl.back()};
    reference.push_back(bulb.de(at));
  }
  const std::string kernels =
      std::string("__kernel void pairs(") + kDeepArguments + ") {\n" + kDeepPoint +
      "  STORE(de_mandelbulb_dd(p, 8.0f, 2.0, (int)iterations, (real_t)pixel), i, out);\n}\n";
  for (int lanes : {1, 16}) {
    const std::string source = program(
        lanes, {"de/powers.cl", "de/mandelbulb.cl", "de/dd.cl", "de/mandelbulb_dd.cl"}, kernels);
    const auto got =
        run(test::runtime(), source, "pairs", lanes, {xh, xl, yh, yl, zh, zl}, {8.0, 0.0});
    for (int k = 0; k < 16; ++k)
      EXPECT_NEAR(got[k], static_cast<double>(reference[k]), 1e-3 * spacing)
          << "lanes " << lanes << ", point " << k;
  }
}

}  // namespace
}  // namespace fr
