// mpi_world_single.cpp — mpi_world.hpp in a build without MPI: always a world of one process.
// Started by a launcher as one of several copies, it refuses to run rather than have every copy
// render the whole job into the same files.
#include "mpi/mpi_world.hpp"

#include "io/atomic_file.hpp"

#include <cstdlib>

namespace fr {
namespace {

const MpiWorld g_world;

// The number of copies a launcher says it started (OpenMPI's mpirun, MPICH's and PMI's), or 1.
long launched_copies() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::strtol(value, nullptr, 10);
  return 1;
}

[[noreturn]] void no_mpi() {
  throw std::logic_error("this fractalis was built without MPI");
}

}  // namespace

bool start_mpi(int*, char***, std::string* problem) {
  const long copies = launched_copies();
  if (copies <= 1) return true;
  *problem = "this fractalis was built without MPI, but a launcher (mpirun, srun) started " +
             std::to_string(copies) +
             " copies of it; build it with MPI (install libopenmpi-dev, then configure with "
             "-DFRACTALIS_MPI=ON) or run one copy";
  return false;
}

void finish_mpi() {}

const MpiWorld& mpi_world() {
  return g_world;
}

std::vector<int> gather_from_all_ranks(int value) {
  return {value};
}

void wait_for_all_ranks() {}

std::string core_binding_problem() {
  return "";
}

void abort_all_ranks(int exit_status) {
  remove_temp_files();
  std::_Exit(exit_status);
}

void send_to_rank(int, int, const std::vector<uint8_t>&) {
  no_mpi();
}
std::optional<RankMessage> poll_any_rank() {
  no_mpi();
}
RankMessage receive_from_rank(int) {
  no_mpi();
}

}  // namespace fr
