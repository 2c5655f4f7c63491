// cl.hpp — the OpenCL C API as this project uses it: one error type for every failing call, and
// move-only owners for the handles (retain/release paired, never leaked on an exception).
#pragma once

#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace fr {

// An OpenCL call failed: which call, its error code and what the caller was doing.
class ClError : public std::runtime_error {
 public:
  ClError(const std::string& call, cl_int code, const std::string& context = "");
  cl_int code() const { return code_; }

 private:
  cl_int code_;
};

const char* cl_error_name(cl_int code);

// Throws ClError when `code` is not CL_SUCCESS.
inline void cl_check(cl_int code, const char* call, const std::string& context = "") {
  if (code != CL_SUCCESS) throw ClError(call, code, context);
}

template <typename Handle, cl_int (*Release)(Handle)>
class ClHandle {
 public:
  ClHandle() = default;
  explicit ClHandle(Handle h) : h_(h) {}
  ~ClHandle() { reset(); }
  ClHandle(ClHandle&& o) noexcept : h_(std::exchange(o.h_, nullptr)) {}
  ClHandle& operator=(ClHandle&& o) noexcept {
    if (this != &o) {
      reset();
      h_ = std::exchange(o.h_, nullptr);
    }
    return *this;
  }
  ClHandle(const ClHandle&) = delete;
  ClHandle& operator=(const ClHandle&) = delete;
  Handle get() const { return h_; }
  explicit operator bool() const { return h_ != nullptr; }
  void reset() {
    if (h_) Release(h_);
    h_ = nullptr;
  }

 private:
  Handle h_ = nullptr;
};

using ClContextHandle = ClHandle<cl_context, clReleaseContext>;
using ClQueueHandle = ClHandle<cl_command_queue, clReleaseCommandQueue>;
using ClProgramHandle = ClHandle<cl_program, clReleaseProgram>;
using ClKernelHandle = ClHandle<cl_kernel, clReleaseKernel>;
using ClBufferHandle = ClHandle<cl_mem, clReleaseMemObject>;

}  // namespace fr
