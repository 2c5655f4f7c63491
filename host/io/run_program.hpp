// run_program.hpp — running a tool (CMake, a compiler) to its end with its output captured, as
// the explorer's edit mode rebuilds a scene's C and shows the compiler's errors in the overlay.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fr {

struct ProgramOutcome {
  bool ok = false;     // started, and exited with status 0
  std::string how;     // "exited with status 2", "could not be started: ..."
  std::string output;  // its stdout and stderr, interleaved as written (the last `max_bytes`)
};

// The program `name` (executable_file_name(name)) in the first folder of the PATH that has it,
// or empty.
std::filesystem::path find_program_on_path(const std::string& name);

// Runs `program` with `arguments` (its stdin the null device) and waits for it to end.
ProgramOutcome run_program(const std::filesystem::path& program,
                           const std::vector<std::string>& arguments,
                           size_t max_bytes = size_t{1} << 20);

}  // namespace fr
