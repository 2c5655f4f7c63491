#include "cli/cli.hpp"

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/watchdog.hpp"
#include "io/echo.hpp"
#include "io/log.hpp"

#include <fractalis/abi.h>

#include <spdlog/spdlog.h>

#include <optional>
#include <ostream>

namespace fr {
namespace {

using CommandFunction = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

// Every command, once: the dispatch, the usage text and the error for an unknown name read it.
struct CommandEntry {
  const char* name;
  const char* summary;  // nullptr: internal, not listed (vet-scene runs in a child process)
  CommandFunction run;
};
const CommandEntry kCommands[] = {
    {"explore", "open the explorer window and fly through a scene", command_explore},
    {"render", "render a scene to a PNG file (or a poster of up to 65535 pixels a side)",
     command_render},
    {"animate", "render a scene along a camera path to a video or a folder of PNGs",
     command_animate},
    {"bench", "time frames of a scene (median, min, max) and count its DE evaluations",
     command_bench},
    {"sweep", "measure image error against frame time over the quality knobs", command_sweep},
    {"list", "list scene plugins, their parameters, or why they failed to load", command_list},
    {"devices", "list OpenCL platforms and devices", command_devices},
    {"check", "run the conformance checks on a scene plugin (for scene authors)", command_check},
    {"cache", "show fractalis's cache folders and their sizes; --clear empties them",
     command_cache},
    {"vet-scene", nullptr, command_vet_scene},
};

std::string usage_text() {
  std::string text =
      "fractalis — real-time explorer and renderer of distance-estimated 3D fractals\n"
      "\n"
      "usage: fractalis <command> [options]\n"
      "\n"
      "commands:\n";
  for (const CommandEntry& c : kCommands)
    if (c.summary) text += "  " + (c.name + std::string(10, ' ')).substr(0, 10) + c.summary + "\n";
  text +=
      "\n"
      "  fractalis <command> --help   options of a command\n"
      "  fractalis --version          versions of fractalis and its scene ABI\n"
      "\n"
      "options of every command (before or after its name):\n"
      "  -v, --verbose      also say what is done step by step (debug messages)\n"
      "  -q, --quiet        say errors only\n"
      "  --log-file FILE    append every message, time-stamped, to FILE as well\n";
  return text;
}

// "explore, render, ... or cache": the listed commands.
std::string command_names() {
  std::vector<const char*> names;
  for (const CommandEntry& c : kCommands)
    if (c.summary) names.push_back(c.name);
  std::string text;
  for (size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
  return text;
}

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
    for (const CommandEntry& c : kCommands)
      if (command == c.name) return c.run(rest, out, err);
    throw UsageError("unknown command '" + echo(command) + "' (expected " + command_names() + ")");
  } catch (const UsageError& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const SceneHangError& e) {
    spdlog::error("{}", e.what());
    return kWatchdogExitStatus;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    (args.empty() ? err : out) << usage_text();
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
