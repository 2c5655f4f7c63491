// OpenCL through the host's own device and runtime code (render/device, render/cl_runtime,
// render/kernel_sources): the display kernel (kernels/post.cl: exposure, ACES filmic fit, sRGB
// with its own log2/exp2) against its formulas in double, over a ramp that covers the whole
// curve. On Linux through the OpenCL loader; cross-built, under Wine through Wine's opencl.dll,
// which passes the calls to this machine's OpenCL (PoCL): the path a Windows build renders
// through. (tests/post_test.cpp checks the same kernel on rendered frames.)
#include "render/cl_runtime.hpp"
#include "render/device.hpp"
#include "render/kernel_sources.hpp"

#include "display_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace fr {
namespace {

using test::display_level;

TEST(PortedOpenCl, TheDisplayKernelMatchesItsFormulas) {
  const std::vector<DeviceInfo> devices = list_devices();
  if (devices.empty()) GTEST_SKIP() << "no OpenCL device on this machine";
  std::string error;
  const std::optional<DeviceInfo> device = select_device(devices, "", &error);
  ASSERT_TRUE(device) << error;
  ClRuntime runtime(*device);
  cl_kernel kernel = runtime.kernel(
      runtime.program(std::string(kernel_source("post.cl")), "-cl-std=CL1.2", "post-processing"),
      "fr_post");

  // Linear values from 1e-6 to 50, spaced evenly in their logarithm, then 0; alpha 0.5.
  constexpr int kQuads = 4096, kPixels = 4 * kQuads;
  std::vector<float> hdr(4 * kPixels);
  for (int p = 0; p < kPixels; ++p) {
    for (int c = 0; c < 3; ++c) {
      const int i = 3 * p + c;
      hdr[4 * p + c] = i == 3 * kPixels - 1
                           ? 0.0f
                           : static_cast<float>(1e-6 * std::pow(5e7, i / (3.0 * kPixels)));
    }
    hdr[4 * p + 3] = 0.5f;
  }
  const float exposure = 1.3f;
  cl_int status = CL_SUCCESS;
  ClBufferHandle in(clCreateBuffer(runtime.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                   hdr.size() * sizeof(float), hdr.data(), &status));
  ASSERT_EQ(status, CL_SUCCESS) << cl_error_name(status);
  ClBufferHandle out(
      clCreateBuffer(runtime.context(), CL_MEM_WRITE_ONLY, 4 * kPixels, nullptr, &status));
  ASSERT_EQ(status, CL_SUCCESS) << cl_error_name(status);
  const cl_mem in_mem = in.get(), out_mem = out.get();
  const int quads = kQuads;
  ASSERT_EQ(clSetKernelArg(kernel, 0, sizeof in_mem, &in_mem), CL_SUCCESS);
  ASSERT_EQ(clSetKernelArg(kernel, 1, sizeof out_mem, &out_mem), CL_SUCCESS);
  ASSERT_EQ(clSetKernelArg(kernel, 2, sizeof exposure, &exposure), CL_SUCCESS);
  ASSERT_EQ(clSetKernelArg(kernel, 3, sizeof quads, &quads), CL_SUCCESS);
  const size_t global = kQuads;
  ASSERT_EQ(clEnqueueNDRangeKernel(runtime.queue(), kernel, 1, nullptr, &global, nullptr, 0,
                                   nullptr, nullptr),
            CL_SUCCESS);
  std::vector<uint8_t> display(4 * kPixels);
  ASSERT_EQ(clEnqueueReadBuffer(runtime.queue(), out_mem, CL_TRUE, 0, display.size(),
                                display.data(), 0, nullptr, nullptr),
            CL_SUCCESS);

  size_t off_by_one = 0, worse = 0;
  for (int i = 0; i < 4 * kPixels; ++i) {
    if (i % 4 == 3) {
      ASSERT_EQ(display[i], 255) << "alpha is opaque";
      continue;
    }
    const int diff = std::abs(int(display[i]) - display_level(hdr[i], exposure));
    off_by_one += diff == 1;
    worse += diff > 1;
  }
  EXPECT_EQ(worse, 0u);
  // Rounding differs only where the value lies within float error of a level's edge.
  EXPECT_LE(off_by_one, size_t{3 * kPixels} / 1000) << "values one level off";
  EXPECT_EQ(display[0], display_level(1e-6, exposure));
  EXPECT_EQ(display[4 * kPixels - 2], 0) << "zero is black";
}

}  // namespace
}  // namespace fr
