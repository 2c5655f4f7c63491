#include "render/cl.hpp"

namespace fr {

ClError::ClError(const std::string& call, cl_int code, const std::string& context)
    : std::runtime_error("OpenCL " + call + " failed: " + cl_error_name(code) + " (" +
                         std::to_string(code) + ")" + (context.empty() ? "" : " while " + context)),
      code_(code) {}

const char* cl_error_name(cl_int code) {
  switch (code) {
#define FR_CL_CASE(c) \
  case c:             \
    return #c;
    FR_CL_CASE(CL_SUCCESS)
    FR_CL_CASE(CL_DEVICE_NOT_FOUND)
    FR_CL_CASE(CL_DEVICE_NOT_AVAILABLE)
    FR_CL_CASE(CL_COMPILER_NOT_AVAILABLE)
    FR_CL_CASE(CL_MEM_OBJECT_ALLOCATION_FAILURE)
    FR_CL_CASE(CL_OUT_OF_RESOURCES)
    FR_CL_CASE(CL_OUT_OF_HOST_MEMORY)
    FR_CL_CASE(CL_BUILD_PROGRAM_FAILURE)
    FR_CL_CASE(CL_INVALID_VALUE)
    FR_CL_CASE(CL_INVALID_PLATFORM)
    FR_CL_CASE(CL_INVALID_DEVICE)
    FR_CL_CASE(CL_INVALID_CONTEXT)
    FR_CL_CASE(CL_INVALID_COMMAND_QUEUE)
    FR_CL_CASE(CL_INVALID_MEM_OBJECT)
    FR_CL_CASE(CL_INVALID_BUILD_OPTIONS)
    FR_CL_CASE(CL_INVALID_PROGRAM)
    FR_CL_CASE(CL_INVALID_PROGRAM_EXECUTABLE)
    FR_CL_CASE(CL_INVALID_KERNEL_NAME)
    FR_CL_CASE(CL_INVALID_KERNEL)
    FR_CL_CASE(CL_INVALID_ARG_INDEX)
    FR_CL_CASE(CL_INVALID_ARG_VALUE)
    FR_CL_CASE(CL_INVALID_ARG_SIZE)
    FR_CL_CASE(CL_INVALID_KERNEL_ARGS)
    FR_CL_CASE(CL_INVALID_WORK_DIMENSION)
    FR_CL_CASE(CL_INVALID_WORK_GROUP_SIZE)
    FR_CL_CASE(CL_INVALID_GLOBAL_WORK_SIZE)
    FR_CL_CASE(CL_INVALID_BUFFER_SIZE)
#undef FR_CL_CASE
    default:
      return "unknown OpenCL error";
  }
}

}  // namespace fr
