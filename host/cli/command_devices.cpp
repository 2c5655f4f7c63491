#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "render/cl_runtime.hpp"
#include "render/dd_selftest.hpp"
#include "render/device.hpp"
#include "render/render_settings.hpp"

#include <spdlog/spdlog.h>

#include <ostream>
#include <stdexcept>

namespace fr {

int command_devices(const std::vector<std::string>& args, std::ostream& out,
                    std::ostream& /*err: messages go to spdlog*/) {
  const std::vector<OptionSpec> specs = {{"help", nullptr, false, "show this help"}};
  auto options = parse_options("devices", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis devices\n\nLists OpenCL platforms and devices with the selector "
           "--device takes,\nand for each with double precision whether double-double "
           "arithmetic (deep zoom)\nkeeps its error terms there (a self-test of its sums and "
           "products).\n\n"
        << format_options(specs);
    return 0;
  }
  const auto devices = list_devices();
  if (devices.empty()) {
    throw std::runtime_error("no OpenCL device found (is pocl-opencl-icd installed?)");
  }
  std::string error;
  const auto chosen = select_device(devices, "", &error);
  int last_platform = -1;
  for (const auto& d : devices) {
    if (d.platform_index != last_platform) {
      out << "platform " << d.platform_index << ": " << d.platform_name << "\n";
      last_platform = d.platform_index;
    }
    const bool is_default = chosen && chosen->selector() == d.selector();
    out << "  " << d.selector() << "  " << d.type_name() << "  " << d.name
        << (is_default ? "  [default]" : "") << "\n"
        << "       " << d.version << ", driver " << d.driver_version << ", " << d.compute_units
        << " compute units, " << (d.global_mem_bytes >> 20) << " MiB, double "
        << (d.has_fp64 ? "yes" : "no") << ", lanes " << preferred_lanes(d, Precision::Float)
        << " (" << preferred_lanes(d, Precision::Double) << " in double)\n";
    // Whether double-double (deep zoom) keeps its error terms here (render/dd_selftest.hpp).
    if (d.has_fp64) {
      try {
        ClRuntime runtime(d);
        const DdSelftest test = dd_selftest(runtime);
        out << "       double-double: " << (test.exact ? "exact" : "NOT exact: " + test.failed)
            << " (" << test.cases << " sums and products checked)\n";
      } catch (const std::exception& e) {
        out << "       double-double: not checked: " << e.what() << "\n";
      }
    }
  }
  return 0;
}

}  // namespace fr
