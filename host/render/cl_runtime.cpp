#include "render/cl_runtime.hpp"

#include <vector>

namespace fr {

ClRuntime::ClRuntime(const DeviceInfo& device) : device_(device) {
  cl_int err = CL_SUCCESS;
  const cl_context_properties props[] = {
      CL_CONTEXT_PLATFORM, reinterpret_cast<cl_context_properties>(device.platform), 0};
  context_ = ClContextHandle(clCreateContext(props, 1, &device.device, nullptr, nullptr, &err));
  cl_check(err, "clCreateContext", "opening device " + device.name);
  queue_ = ClQueueHandle(clCreateCommandQueue(context_.get(), device.device, 0, &err));
  cl_check(err, "clCreateCommandQueue", "opening device " + device.name);
}

std::string first_build_error(const std::string& message) {
  const size_t at = message.find("\nerror: ");
  if (at == std::string::npos) return message;
  return message.substr(at + 1, message.find('\n', at + 1) - at - 1);
}

cl_program ClRuntime::program(const std::string& source, const std::string& options,
                              const std::string& description) {
  const std::hash<std::string> hash;
  const size_t key = hash(source) ^ (hash(options) * 0x9e3779b97f4a7c15ull);
  for (auto [it, end] = programs_.equal_range(key); it != end; ++it)
    if (it->second.source == source && it->second.options == options)
      return it->second.program.get();

  cl_int err = CL_SUCCESS;
  const char* text = source.c_str();
  const size_t length = source.size();
  ClProgramHandle program(clCreateProgramWithSource(context_.get(), 1, &text, &length, &err));
  cl_check(err, "clCreateProgramWithSource", "building " + description);
  if (on_build) on_build(&description);
  err = clBuildProgram(program.get(), 1, &device_.device, options.c_str(), nullptr, nullptr);
  if (on_build) on_build(nullptr);
  if (err != CL_SUCCESS) {
    size_t log_size = 0;
    clGetProgramBuildInfo(program.get(), device_.device, CL_PROGRAM_BUILD_LOG, 0, nullptr,
                          &log_size);
    std::string log(log_size, '\0');
    clGetProgramBuildInfo(program.get(), device_.device, CL_PROGRAM_BUILD_LOG, log_size, log.data(),
                          nullptr);
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    throw KernelBuildError(description + " failed to compile on " + device_.name + " (" +
                           cl_error_name(err) + "):\n" + log);
  }
  ++programs_built_;
  cl_program raw = program.get();
  programs_.emplace(key, CachedProgram{source, options, std::move(program)});
  return raw;
}

cl_kernel ClRuntime::kernel(cl_program program, const char* name) {
  auto key = std::make_pair(program, std::string(name));
  if (auto it = kernels_.find(key); it != kernels_.end()) return it->second.get();
  cl_int err = CL_SUCCESS;
  ClKernelHandle k(clCreateKernel(program, name, &err));
  cl_check(err, "clCreateKernel", std::string("creating kernel ") + name);
  cl_kernel raw = k.get();
  kernels_.emplace(key, std::move(k));
  return raw;
}

}  // namespace fr
