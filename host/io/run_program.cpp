#include "io/run_program.hpp"

#include "platform/channel.hpp"
#include "platform/child_process.hpp"

#include <cstdlib>

namespace fr {

std::filesystem::path find_program_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  const std::string folders = path;
  size_t start = 0;
  while (start <= folders.size()) {
    size_t end = folders.find(path_list_separator(), start);
    if (end == std::string::npos) end = folders.size();
    if (end > start) {
      const std::filesystem::path candidate =
          std::filesystem::path(folders.substr(start, end - start)) / executable_file_name(name);
      if (is_executable_file(candidate)) return candidate;
    }
    start = end + 1;
  }
  return {};
}

ProgramOutcome run_program(const std::filesystem::path& program,
                           const std::vector<std::string>& arguments, size_t max_bytes) {
  ProgramOutcome outcome;
  ChannelPair pipe;
  std::string error;
  if (!make_pipe(&pipe, &error)) {
    outcome.how = "could not be started: " + error;
    return outcome;
  }
  ChildSpec spec;
  spec.program = program;
  spec.arguments = arguments;
  spec.stdout_to = pipe.theirs.handle();
  spec.stderr_to = pipe.theirs.handle();
  std::unique_ptr<ChildProcess> child = ChildProcess::start(spec, &error);
  pipe.theirs.close();  // ours reads until the child's end closes
  if (!child) {
    outcome.how = "could not be started: " + error;
    return outcome;
  }
  char buffer[16384];
  for (;;) {
    size_t got = 0;
    if (pipe.ours.read_some(buffer, sizeof buffer, -1, &got) != ChannelStatus::Ok) break;
    outcome.output.append(buffer, got);
    if (outcome.output.size() > 2 * max_bytes)
      outcome.output.erase(0, outcome.output.size() - max_bytes);
  }
  if (outcome.output.size() > max_bytes)
    outcome.output.erase(0, outcome.output.size() - max_bytes);
  child->wait(-1);
  outcome.how = child->how_it_ended();
  outcome.ok = child->exit_status() == 0;
  return outcome;
}

}  // namespace fr
