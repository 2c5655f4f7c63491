// mpi_world.hpp — the processes of an MPI job (`mpirun -np N fractalis ...`, `srun fractalis ...`):
// which one this is, how many there are, and the few messages shared_tasks.hpp sends between
// them. The one file that calls MPI is mpi_world.cpp; a build without MPI has
// mpi_world_single.cpp instead, a world of one process.
//
// fractalis notices by itself that a launcher started it (the environment every launcher sets:
// OpenMPI's OMPI_COMM_WORLD_SIZE, PMIx's PMIX_RANK, PMI's PMI_SIZE as MPICH and srun --mpi=pmi2
// set it), and only then starts MPI; run any other way it is one process, as if MPI were not
// there. A job of one rank behaves exactly like that too.
//
// Threads: every function here is called from the main thread only (MPI_THREAD_FUNNELED).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fr {

struct MpiWorld {
  int rank = 0;  // 0 hands out the work and writes the output (shared_tasks.hpp)
  int size = 1;  // processes in the job; 1 outside a launcher
  // More than one process: commands that share work do, the others run on rank 0 alone.
  bool shared() const { return size > 1; }
};

// Starts MPI when a launcher started this process (see above). Returns false with *problem
// when it cannot: MPI fails to start, or this build has no MPI but the launcher started
// several copies of it (each would render everything and overwrite the others' files).
bool start_mpi(int* argc, char*** argv, std::string* problem);
// Ends MPI after the command, when start_mpi started it (every rank must get here).
void finish_mpi();
// The world start_mpi found; one process before it or without a launcher.
const MpiWorld& mpi_world();

// Every rank passes its own value and gets everyone's, by rank (a collective: every rank must
// call it, in the same order). A world of one gets its own value back.
std::vector<int> gather_from_all_ranks(int value);

// When this process may run on fewer cores than the machine has (its CPU affinity: mpirun binds
// each rank of a small job to one core by default), what to say about it; else empty. A rank
// renders with every core it may use, as fractalis alone does.
std::string core_binding_problem();

// Waits until every rank has called it (a collective, like gather_from_all_ranks), by polling:
// a rank that waits long (its share of the work done) leaves its core to the others.
void wait_for_all_ranks();

// Ends every process of the job at once with `exit_status` (the launcher reports it). For a
// rank that died or hangs: nothing else would end the others.
[[noreturn]] void abort_all_ranks(int exit_status);

// Messages between ranks: a tag (0 to 99) and bytes. Sizes over 2 GiB travel in pieces.
struct RankMessage {
  int from = -1;
  int tag = 0;
  std::vector<uint8_t> bytes;
};
void send_to_rank(int rank, int tag, const std::vector<uint8_t>& bytes);
// The next message from any rank, if one has arrived; never waits.
std::optional<RankMessage> poll_any_rank();
// Waits for the next message from `rank`.
RankMessage receive_from_rank(int rank);

}  // namespace fr
