// commands.hpp — one function per `fractalis` command. Each returns the process exit code
// (0 success, 1 failure while working, 2 bad usage) and writes only to `out` and `err`.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace fr {

int command_render(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_animate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_bench(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_list(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_explore(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_sweep(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_check(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
// Hidden: the explorer's test render of a scene in a child process (render/scene_vetting.hpp).
int command_vet_scene(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_cache(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_devices(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace fr
