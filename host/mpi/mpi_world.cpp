// mpi_world.cpp — mpi_world.hpp over MPI (a build with FRACTALIS_MPI and MPI found).
#include "mpi/mpi_world.hpp"

#include "io/atomic_file.hpp"

#include <mpi.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <thread>

namespace fr {
namespace {

MpiWorld g_world;
bool g_started = false;

bool launched_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

// One message travels as a header (its size) and then pieces of at most kPieceBytes, since MPI
// counts in int.
constexpr size_t kPieceBytes = size_t{1} << 30;
// The header's tag: the message's own tag plus this. Tags stay far below 32767, the least upper
// bound (MPI_TAG_UB) the standard lets an MPI library have.
constexpr int kSizeTagOffset = 100;

}  // namespace

bool start_mpi(int* argc, char*** argv, std::string* problem) {
  if (!launched_by_mpi_launcher()) return true;
  int provided = 0;
  if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    *problem = "MPI did not start (started by mpirun or srun?)";
    return false;
  }
  g_started = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_world.size);
  return true;
}

void finish_mpi() {
  if (!g_started) return;
  g_started = false;
  MPI_Finalize();
}

const MpiWorld& mpi_world() {
  return g_world;
}

std::vector<int> gather_from_all_ranks(int value) {
  std::vector<int> all(static_cast<size_t>(g_world.size), value);
  if (g_started) MPI_Allgather(&value, 1, MPI_INT, all.data(), 1, MPI_INT, MPI_COMM_WORLD);
  return all;
}

void wait_for_all_ranks() {
  if (!g_started) return;
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

std::string core_binding_problem() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return "";
  const int allowed = CPU_COUNT(&set);
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  if (online <= 0 || allowed >= online) return "";
  return "rank " + std::to_string(g_world.rank) + " may run on " + std::to_string(allowed) +
         " of this machine's " + std::to_string(online) +
         " cores (the launcher bound it), and renders on those alone; mpirun --bind-to none "
         "(or srun --cpu-bind=none) lets each rank use every core";
}

void abort_all_ranks(int exit_status) {
  remove_temp_files();
  if (g_started) MPI_Abort(MPI_COMM_WORLD, exit_status);
  std::_Exit(exit_status);
}

void send_to_rank(int rank, int tag, const std::vector<uint8_t>& bytes) {
  const uint64_t size = bytes.size();
  MPI_Send(&size, 1, MPI_UINT64_T, rank, tag + kSizeTagOffset, MPI_COMM_WORLD);
  for (size_t at = 0; at < bytes.size(); at += kPieceBytes) {
    const int piece = static_cast<int>(std::min(kPieceBytes, bytes.size() - at));
    MPI_Send(bytes.data() + at, piece, MPI_BYTE, rank, tag, MPI_COMM_WORLD);
  }
}

namespace {

// The rest of a message whose header (its size) came from `from` with `header_tag`.
RankMessage receive_body(int from, int header_tag) {
  RankMessage m;
  m.from = from;
  m.tag = header_tag - kSizeTagOffset;
  uint64_t size = 0;
  MPI_Recv(&size, 1, MPI_UINT64_T, from, header_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  m.bytes.resize(size);
  for (size_t at = 0; at < size; at += kPieceBytes) {
    const int piece = static_cast<int>(std::min<uint64_t>(kPieceBytes, size - at));
    MPI_Recv(m.bytes.data() + at, piece, MPI_BYTE, from, m.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  return m;
}

bool is_header_tag(int tag) {
  return tag >= kSizeTagOffset;
}

}  // namespace

std::optional<RankMessage> poll_any_rank() {
  // Only headers start a message: the pieces of a message follow its header from the same rank
  // (MPI keeps the order of one sender's messages), so they are received with it.
  for (;;) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return std::nullopt;
    if (is_header_tag(status.MPI_TAG)) return receive_body(status.MPI_SOURCE, status.MPI_TAG);
    // A piece without its header cannot arrive first; were one there, waiting would not help.
    abort_all_ranks(1);
  }
}

RankMessage receive_from_rank(int rank) {
  // Polled, not MPI_Probe: Open MPI's blocking calls spin on a core, and the rank waited for
  // may be rank 0 encoding on the same machine.
  MPI_Status status;
  for (int flag = 0;;) {
    MPI_Iprobe(rank, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (flag) break;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  if (!is_header_tag(status.MPI_TAG)) abort_all_ranks(1);
  return receive_body(rank, status.MPI_TAG);
}

}  // namespace fr
