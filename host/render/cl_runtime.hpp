// cl_runtime.hpp — one OpenCL device in use: its context, its queue, and the programs built
// for it, cached by source and build options.
#pragma once

#include "render/cl.hpp"
#include "render/device.hpp"

#include <functional>
#include <map>
#include <stdexcept>
#include <string>

namespace fr {

// A program failed to compile. what() names the scene, lanes, precision and stages, then gives
// the compiler's log, whose file:line references point into the scene's own source.
class KernelBuildError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The first "error: ..." line of a build failure's message (all of it when it has none).
std::string first_build_error(const std::string& message);

class ClRuntime {
 public:
  explicit ClRuntime(const DeviceInfo& device);
  ClRuntime(const ClRuntime&) = delete;
  ClRuntime& operator=(const ClRuntime&) = delete;

  const DeviceInfo& device() const { return device_; }
  cl_context context() const { return context_.get(); }
  cl_command_queue queue() const { return queue_.get(); }

  // The built program for this source and options: from the cache, or compiled now (throws
  // KernelBuildError with `description` and the build log).
  cl_program program(const std::string& source, const std::string& options,
                     const std::string& description);
  // A kernel object of a cached program, made once.
  cl_kernel kernel(cl_program program, const char* name);

  size_t programs_built() const { return programs_built_; }
  // Called with the program's description just before a build (not for a cached program) and
  // with null when it has ended, built or not: the render worker tells fractalis, which allows a
  // build more time than a frame (worker/render_worker.hpp).
  std::function<void(const std::string* building)> on_build;

 private:
  DeviceInfo device_;
  ClContextHandle context_;
  ClQueueHandle queue_;
  // A frame asks for its programs every time (a render kernel's source is ~100 KB): found by a
  // hash of source and options that costs ~12 us per 100 KB (FNV-1a cost 95), then compared in
  // full, so that two sources with the same hash are two programs.
  struct CachedProgram {
    std::string source;
    std::string options;
    ClProgramHandle program;
  };
  std::multimap<size_t, CachedProgram> programs_;
  std::map<std::pair<cl_program, std::string>, ClKernelHandle> kernels_;
  size_t programs_built_ = 0;
};

}  // namespace fr
