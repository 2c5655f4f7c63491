#include "cli/cli.hpp"

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/watchdog.hpp"
#include "io/echo.hpp"
#include "io/log.hpp"
#include "mpi/mpi_world.hpp"
#include "mpi/shared_tasks.hpp"
#include "worker/render_worker.hpp"

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
  // In an MPI job every rank runs it (it shares its work out); any other command runs on rank
  // 0 alone (a benchmark or sweep then times one process, undisturbed by the others).
  bool shared_by_ranks = false;
};
const CommandEntry kCommands[] = {
    {"explore", "open the explorer window and fly through a scene", command_explore},
    {"render", "render a scene to a PNG file (or a poster of up to 65535 pixels a side)",
     command_render, true},
    {"animate", "render a scene along a camera path to a video or a folder of PNGs",
     command_animate, true},
    {"bench", "time frames of a scene (median, min, max) and count its DE evaluations",
     command_bench},
    {"sweep", "measure image error against frame time over the quality knobs", command_sweep},
    {"list", "list scene plugins, their parameters, or why they failed to load", command_list},
    {"gallery", "render every scene and preset into a folder with an index.html contact sheet",
     command_gallery},
    {"new", "write, build and install a new scene project (for scene authors)", command_new},
    {"devices", "list OpenCL platforms and devices", command_devices},
    {"check", "run the conformance checks on a scene plugin (for scene authors)", command_check},
    {"import", "import a Mandelbulber2 settings file (.fract) as a preset", command_import},
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
  } catch (const AlreadyReported& e) {
    return e.exit_status;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return exit_status_of(std::current_exception());
  }
}

bool is_shared_by_ranks(const std::string& command) {
  for (const CommandEntry& c : kCommands)
    if (command == c.name) return c.shared_by_ranks;
  return false;
}

// In an MPI job, whether this rank runs `command` at all: rank 0 runs everything; the others
// only a command that shares its work, and not its --help.
bool runs_on_this_rank(const std::string& command, const std::vector<std::string>& rest) {
  if (mpi_world().rank == 0) return true;
  for (const std::string& a : rest)
    if (a == "--help" || a == "-h") return false;
  return is_shared_by_ranks(command);
}

}  // namespace

int exit_status_of(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const UsageError&) {
    return 2;
  } catch (const SceneHangError&) {
    return kWatchdogExitStatus;
  } catch (const RenderWorkerFailure& e) {  // a DE that never returns, a compile that never ends
    return e.timed_out() ? kWatchdogExitStatus : 1;
  } catch (const AlreadyReported& e) {
    return e.exit_status;
  } catch (...) {
    return 1;
  }
}

void agree_across_ranks(std::exception_ptr failure) {
  const MpiWorld& world = mpi_world();
  if (!world.shared()) {
    if (failure) std::rethrow_exception(failure);
    return;
  }
  const std::vector<int> statuses = gather_from_all_ranks(failure ? exit_status_of(failure) : 0);
  for (int rank = 0; rank < world.size; ++rank) {
    if (statuses[rank] == 0) continue;
    if (rank != world.rank) throw AlreadyReported(statuses[rank]);
    if (rank == 0) std::rethrow_exception(failure);
    try {
      std::rethrow_exception(failure);
    } catch (const std::exception& e) {
      spdlog::error("rank {}: {}", rank, e.what());
    }
    throw AlreadyReported(statuses[rank]);
  }
}

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  // In an MPI job the usage, the version and errors in them are rank 0's to say.
  const bool rank_zero = mpi_world().rank == 0;
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help" ||
      args[0] == "--version")
    if (!rank_zero) return args.empty() ? 2 : 0;
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
    if (rank_zero) err << "fractalis: error: " << e.what() << "\n";
    return 2;
  }
  const std::string command = args_left[0];
  const std::vector<std::string> rest(args_left.begin() + 1, args_left.end());
  if (!runs_on_this_rank(command, rest)) return 0;
  if (rank_zero && mpi_world().shared() && !is_shared_by_ranks(command))
    spdlog::info("'{}' runs on rank 0 alone; ranks 1 to {} have nothing to do", echo(command),
                 mpi_world().size - 1);
  return run_command(command, rest, out, err);
}

}  // namespace fr
