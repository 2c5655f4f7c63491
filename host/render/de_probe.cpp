#include "render/de_probe.hpp"

#include "render/kernel_assembly.hpp"

static_assert(sizeof(std::array<float, 3>) == 3 * sizeof(float),
              "points are uploaded as packed xyz");

namespace fr {

std::vector<float> probe_de(ClRuntime& runtime, const SceneInfo& info,
                            const std::vector<fr_value>& params,
                            const std::vector<std::array<float, 3>>& points, int lanes,
                            Precision precision) {
  if (points.empty()) return {};
  lanes = resolve_lanes(lanes, &runtime.device());
  const AssembledKernel k = assemble_probe_kernel(info, params, KernelConfig{lanes, precision});
  cl_kernel kernel =
      runtime.kernel(runtime.program(k.source, k.build_options, k.description), "fr_probe_de");

  const std::vector<uint8_t> packed = pack_scene_params(info, params);
  cl_int err = CL_SUCCESS;
  const size_t n = points.size();
  ClBufferHandle param_buf(clCreateBuffer(runtime.context(),
                                          CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, packed.size(),
                                          const_cast<uint8_t*>(packed.data()), &err));
  cl_check(err, "clCreateBuffer", "probe parameters");
  ClBufferHandle point_buf(clCreateBuffer(
      runtime.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * 3 * sizeof(float),
      const_cast<std::array<float, 3>*>(points.data()), &err));
  cl_check(err, "clCreateBuffer", "probe points");
  ClBufferHandle out_buf(
      clCreateBuffer(runtime.context(), CL_MEM_WRITE_ONLY, n * sizeof(float), nullptr, &err));
  cl_check(err, "clCreateBuffer", "probe results");

  cl_mem pb = param_buf.get(), xb = point_buf.get(), ob = out_buf.get();
  const cl_int count = static_cast<cl_int>(n);
  cl_check(clSetKernelArg(kernel, 0, sizeof pb, &pb), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, 1, sizeof xb, &xb), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, 2, sizeof ob, &ob), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, 3, sizeof count, &count), "clSetKernelArg");
  const size_t global = (n + lanes - 1) / lanes;
  cl_check(clEnqueueNDRangeKernel(runtime.queue(), kernel, 1, nullptr, &global, nullptr, 0, nullptr,
                                  nullptr),
           "clEnqueueNDRangeKernel", "probing " + k.description);
  std::vector<float> out(n);
  cl_check(clEnqueueReadBuffer(runtime.queue(), ob, CL_TRUE, 0, n * sizeof(float), out.data(), 0,
                               nullptr, nullptr),
           "clEnqueueReadBuffer", "reading probe results");
  return out;
}

std::vector<float> probe_material(ClRuntime& runtime, const SceneInfo& info,
                                  const std::vector<fr_value>& params, const fr_frame_constants& fc,
                                  const std::vector<std::array<float, 3>>& points) {
  if (points.empty()) return {};
  const int lanes = resolve_lanes(0, &runtime.device());
  const AssembledKernel k =
      assemble_material_probe_kernel(info, params, KernelConfig{lanes, Precision::Float});
  cl_kernel kernel = runtime.kernel(runtime.program(k.source, k.build_options, k.description),
                                    "fr_probe_material");
  const std::vector<uint8_t> packed = pack_scene_params(info, params);
  const size_t n = points.size();
  cl_context ctx = runtime.context();
  cl_int err = CL_SUCCESS;
  ClBufferHandle fc_buf(clCreateBuffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof fc,
                                       const_cast<fr_frame_constants*>(&fc), &err));
  cl_check(err, "clCreateBuffer", "material probe constants");
  ClBufferHandle param_buf(clCreateBuffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                          packed.size(), const_cast<uint8_t*>(packed.data()),
                                          &err));
  cl_check(err, "clCreateBuffer", "material probe parameters");
  ClBufferHandle point_buf(clCreateBuffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                          n * 3 * sizeof(float),
                                          const_cast<std::array<float, 3>*>(points.data()), &err));
  cl_check(err, "clCreateBuffer", "material probe points");
  ClBufferHandle out_buf(
      clCreateBuffer(ctx, CL_MEM_WRITE_ONLY, n * kMaterialFloats * sizeof(float), nullptr, &err));
  cl_check(err, "clCreateBuffer", "material probe results");
  cl_mem fb = fc_buf.get(), pb = param_buf.get(), xb = point_buf.get(), ob = out_buf.get();
  const cl_int count = static_cast<cl_int>(n);
  cl_check(clSetKernelArg(kernel, 0, sizeof fb, &fb), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, 1, sizeof pb, &pb), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, 2, sizeof xb, &xb), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, 3, sizeof ob, &ob), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, 4, sizeof count, &count), "clSetKernelArg");
  const size_t global = (n + lanes - 1) / lanes;
  cl_check(clEnqueueNDRangeKernel(runtime.queue(), kernel, 1, nullptr, &global, nullptr, 0, nullptr,
                                  nullptr),
           "clEnqueueNDRangeKernel", "probing " + k.description);
  std::vector<float> out(n * kMaterialFloats);
  cl_check(clEnqueueReadBuffer(runtime.queue(), ob, CL_TRUE, 0, out.size() * sizeof(float),
                               out.data(), 0, nullptr, nullptr),
           "clEnqueueReadBuffer", "reading material probe results");
  return out;
}

}  // namespace fr
