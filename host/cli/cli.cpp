#include "cli/cli.hpp"

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "render/cl.hpp"
#include "render/cl_runtime.hpp"

#include <fractalis/abi.h>

#include <ostream>

namespace fr {
namespace {

const char* kUsage =
    "fractalis — real-time explorer and renderer of distance-estimated 3D fractals\n"
    "\n"
    "usage: fractalis <command> [options]\n"
    "\n"
    "commands:\n"
    "  explore   open the explorer window and fly through a scene\n"
    "  render    render a scene to a PNG file\n"
    "  bench     time frames of a scene (median, min, max)\n"
    "  sweep     measure image error against frame time over the quality knobs\n"
    "  list      list scene plugins, their parameters, or why they failed to load\n"
    "  devices   list OpenCL platforms and devices\n"
    "  check     run the conformance checks on a scene plugin (for scene authors)\n"
    "\n"
    "  fractalis <command> --help   options of a command\n"
    "  fractalis --version          versions of fractalis and its scene ABI\n";

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    (args.empty() ? err : out) << kUsage;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    out << "fractalis " << FRACTALIS_VERSION << " (scene ABI " << FR_ABI_VERSION_MAJOR << "."
        << FR_ABI_VERSION_MINOR << ")\n";
    return 0;
  }
  const std::string command = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (command == "explore") return command_explore(rest, out, err);
    if (command == "render") return command_render(rest, out, err);
    if (command == "bench") return command_bench(rest, out, err);
    if (command == "sweep") return command_sweep(rest, out, err);
    if (command == "list") return command_list(rest, out, err);
    if (command == "devices") return command_devices(rest, out, err);
    if (command == "check") return command_check(rest, out, err);
    if (command == "vet-scene") return command_vet_scene(rest, out, err);
    throw UsageError("unknown command '" + command +
                     "' (expected explore, render, bench, sweep, list, devices or check)");
  } catch (const UsageError& e) {
    err << "fractalis: error: " << e.what() << "\n";
    return 2;
  } catch (const KernelBuildError& e) {
    err << "fractalis: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    err << "fractalis: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fr
