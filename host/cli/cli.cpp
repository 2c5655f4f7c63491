#include "cli/cli.hpp"

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "io/echo.hpp"
#include "io/log.hpp"

#include <fractalis/abi.h>

#include <spdlog/spdlog.h>

#include <optional>
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
    "  render    render a scene to a PNG file (or a poster of up to 65535 pixels a side)\n"
    "  animate   render a scene along a camera path to a video or a folder of PNGs\n"
    "  bench     time frames of a scene (median, min, max)\n"
    "  sweep     measure image error against frame time over the quality knobs\n"
    "  list      list scene plugins, their parameters, or why they failed to load\n"
    "  devices   list OpenCL platforms and devices\n"
    "  check     run the conformance checks on a scene plugin (for scene authors)\n"
    "  cache     show fractalis's cache folders and their sizes; --clear empties them\n"
    "\n"
    "  fractalis <command> --help   options of a command\n"
    "  fractalis --version          versions of fractalis and its scene ABI\n"
    "\n"
    "options of every command (before or after its name):\n"
    "  -v, --verbose      also say what is done step by step (debug messages)\n"
    "  -q, --quiet        say errors only\n"
    "  --log-file FILE    append every message, time-stamped, to FILE as well\n";

// Takes the options every command has out of `args`.
LogOptions take_log_options(std::vector<std::string>& args) {
  LogOptions log;
  bool verbose = false, quiet = false;
  std::vector<std::string> rest;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-v" || a == "--verbose") {
      verbose = true;
    } else if (a == "-q" || a == "--quiet") {
      quiet = true;
    } else if (a == "--log-file" || a.rfind("--log-file=", 0) == 0) {
      std::string file = a == "--log-file" ? (i + 1 < args.size() ? args[++i] : "") : a.substr(11);
      if (file.empty()) throw UsageError("--log-file: expected a file name");
      check_output_file("--log-file", file);
      log.file = file;
    } else {
      rest.push_back(a);
    }
  }
  if (verbose && quiet) throw UsageError("--verbose and --quiet: choose one");
  log.verbosity = verbose ? LogVerbosity::Verbose
                  : quiet ? LogVerbosity::Quiet
                          : LogVerbosity::Normal;
  args = std::move(rest);
  return log;
}

int run_command(const std::string& command, const std::vector<std::string>& rest, std::ostream& out,
                std::ostream& err) {
  try {
    if (command == "explore") return command_explore(rest, out, err);
    if (command == "render") return command_render(rest, out, err);
    if (command == "animate") return command_animate(rest, out, err);
    if (command == "bench") return command_bench(rest, out, err);
    if (command == "sweep") return command_sweep(rest, out, err);
    if (command == "list") return command_list(rest, out, err);
    if (command == "devices") return command_devices(rest, out, err);
    if (command == "check") return command_check(rest, out, err);
    if (command == "cache") return command_cache(rest, out, err);
    if (command == "vet-scene") return command_vet_scene(rest, out, err);
    throw UsageError("unknown command '" + echo(command) +
                     "' (expected explore, render, bench, sweep, list, devices, check or cache)");
  } catch (const UsageError& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}

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
  std::vector<std::string> args_left = args;
  std::optional<LogSession> log;
  try {
    const LogOptions log_options = take_log_options(args_left);
    if (args_left.empty()) throw UsageError("no command given (try fractalis --help)");
    log.emplace(err, log_options);
  } catch (const std::exception& e) {
    err << "fractalis: error: " << e.what() << "\n";
    return 2;
  }
  const std::string command = args_left[0];
  return run_command(command, std::vector<std::string>(args_left.begin() + 1, args_left.end()), out,
                     err);
}

}  // namespace fr
