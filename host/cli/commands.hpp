// commands.hpp — one function per `fractalis` command. Each returns the process exit code
// (0 success, 1 failure while working, 2 bad usage) and writes only to `out` and `err`.
#pragma once

#include <exception>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace fr {

// The exit code a command ends with when it throws `failure`: 2 for bad usage (UsageError), 3
// for a scene whose DE never returns, the status of an AlreadyReported, otherwise 1.
int exit_status_of(std::exception_ptr failure);

// In an MPI job (mpi/mpi_world.hpp), every rank says whether it got ready for its part
// (`failure`: null if it did) and learns whether all did; a command that shares its work calls
// it once every rank has read its options and scene. When one failed, every rank throws: the
// lowest failing rank its own error (naming the rank unless it is 0), the others AlreadyReported
// with that rank's exit status, so the error is said once. Outside MPI it rethrows `failure`.
void agree_across_ranks(std::exception_ptr failure);

// `prepare()`'s result on every rank, once every rank has prepared (agree_across_ranks).
template <typename Prepare>
auto prepare_on_every_rank(Prepare prepare) -> decltype(prepare()) {
  std::optional<decltype(prepare())> prepared;
  std::exception_ptr failure;
  try {
    prepared.emplace(prepare());
  } catch (...) {
    failure = std::current_exception();
  }
  agree_across_ranks(failure);
  return std::move(*prepared);
}

int command_render(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_animate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_bench(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_list(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_gallery(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_new(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_explore(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_sweep(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_check(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_import(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
// Hidden: the explorer's test render of a scene in a child process (render/scene_vetting.hpp).
int command_vet_scene(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_cache(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int command_devices(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace fr
