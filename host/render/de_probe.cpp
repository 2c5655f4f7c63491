#include "render/de_probe.hpp"

#include "render/kernel_assembly.hpp"

#include <algorithm>

static_assert(sizeof(std::array<float, 3>) == 3 * sizeof(float),
              "points are uploaded as packed xyz");

namespace fr {
namespace {

struct ProbeInput {
  const void* data;
  size_t bytes;
  const char* what;
};

// Runs probe kernel `name` of `k` over `count` points, FR_LANES a work-item: its arguments are
// `inputs` (copied to read-only buffers), then the output (`floats_per_point` a point), then the
// count.
std::vector<float> run_probe(ClRuntime& runtime, const AssembledKernel& k, const char* name,
                             const std::vector<ProbeInput>& inputs, size_t count, int lanes,
                             size_t floats_per_point) {
  cl_kernel kernel =
      runtime.kernel(runtime.program(k.source, k.build_options, k.description), name);
  std::vector<ClBufferHandle> buffers;
  cl_uint arg = 0;
  for (const ProbeInput& in : inputs) {
    cl_int err = CL_SUCCESS;
    buffers.emplace_back(clCreateBuffer(runtime.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                        in.bytes, const_cast<void*>(in.data), &err));
    cl_check(err, "clCreateBuffer", in.what);
    const cl_mem b = buffers.back().get();
    cl_check(clSetKernelArg(kernel, arg++, sizeof b, &b), "clSetKernelArg");
  }
  const size_t out_bytes = count * floats_per_point * sizeof(float);
  cl_int err = CL_SUCCESS;
  ClBufferHandle out_buf(
      clCreateBuffer(runtime.context(), CL_MEM_WRITE_ONLY, out_bytes, nullptr, &err));
  cl_check(err, "clCreateBuffer", "probe results");
  const cl_mem ob = out_buf.get();
  const cl_int n = static_cast<cl_int>(count);
  cl_check(clSetKernelArg(kernel, arg++, sizeof ob, &ob), "clSetKernelArg");
  cl_check(clSetKernelArg(kernel, arg++, sizeof n, &n), "clSetKernelArg");
  const size_t global = (count + lanes - 1) / lanes;
  cl_check(clEnqueueNDRangeKernel(runtime.queue(), kernel, 1, nullptr, &global, nullptr, 0, nullptr,
                                  nullptr),
           "clEnqueueNDRangeKernel", "probing " + k.description);
  std::vector<float> out(count * floats_per_point);
  cl_check(clEnqueueReadBuffer(runtime.queue(), ob, CL_TRUE, 0, out_bytes, out.data(), 0, nullptr,
                               nullptr),
           "clEnqueueReadBuffer", "reading probe results");
  return out;
}

// Probes serve checks and tests, not speed: unless asked for a width, one packet wide, which
// every scene's code builds at (a wide one may not: wide_lanes.cl).
int probe_lanes(int requested, const DeviceInfo& device) {
  return requested > 0 ? requested
                       : std::min(kPacketLanes, resolve_lanes(0, &device, Precision::Float));
}

}  // namespace

std::vector<float> probe_de(ClRuntime& runtime, const SceneInfo& info,
                            const std::vector<fr_value>& params,
                            const std::vector<std::array<float, 3>>& points, int lanes,
                            Precision precision, const PairOrigin* origin) {
  if (points.empty()) return {};
  lanes = probe_lanes(lanes, runtime.device());
  const AssembledKernel k = assemble_probe_kernel(info, params, KernelConfig{lanes, precision});
  const PairOrigin world_origin{};
  if (precision == Precision::DoubleDouble && !origin) origin = &world_origin;
  const std::vector<uint8_t> packed =
      pack_scene_params(info, params, precision == Precision::DoubleDouble ? origin : nullptr);
  return run_probe(runtime, k, "fr_probe_de",
                   {{packed.data(), packed.size(), "probe parameters"},
                    {points.data(), points.size() * sizeof(points[0]), "probe points"}},
                   points.size(), lanes, 1);
}

std::vector<float> probe_material(ClRuntime& runtime, const SceneInfo& info,
                                  const std::vector<fr_value>& params, const fr_frame_constants& fc,
                                  const std::vector<std::array<float, 3>>& points) {
  if (points.empty()) return {};
  const int lanes = probe_lanes(0, runtime.device());
  const AssembledKernel k =
      assemble_material_probe_kernel(info, params, KernelConfig{lanes, Precision::Float});
  const std::vector<uint8_t> packed = pack_scene_params(info, params);
  return run_probe(runtime, k, "fr_probe_material",
                   {{&fc, sizeof fc, "material probe constants"},
                    {packed.data(), packed.size(), "material probe parameters"},
                    {points.data(), points.size() * sizeof(points[0]), "material probe points"}},
                   points.size(), lanes, kMaterialFloats);
}

std::vector<float> probe_albedo(ClRuntime& runtime, const SceneInfo& info,
                                const std::vector<fr_value>& params,
                                const std::vector<std::array<float, 3>>& points,
                                Precision precision) {
  if (points.empty()) return {};
  const int lanes = probe_lanes(0, runtime.device());
  const AssembledKernel k =
      assemble_material_probe_kernel(info, params, KernelConfig{lanes, precision});
  const std::vector<uint8_t> packed = pack_scene_params(info, params);
  return run_probe(runtime, k, "fr_probe_albedo",
                   {{packed.data(), packed.size(), "albedo probe parameters"},
                    {points.data(), points.size() * sizeof(points[0]), "albedo probe points"}},
                   points.size(), lanes, 3);
}

}  // namespace fr
