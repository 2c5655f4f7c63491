// shared_tasks.hpp — a job's tasks (an animation's frames, a poster's bands) shared out among the
// ranks of an MPI job (mpi_world.hpp).
//
// Rank 0 leads: it renders nothing, hands each task to the next rank that asks (so a slow task
// holds no other rank back), and takes the results back in the order of the task list, however
// they arrive, for one writer (a video encoder, a PNG or EXR stream). Every other rank serves:
// asks, does the task it is given, sends the result and asks again, until rank 0 dismisses it.
//
// Faults: a task that throws on its rank is reported by rank 0 with the rank and the task, the
// others are dismissed, and every rank ends with exit status 1. A rank that dies ends the job
// through the launcher (mpirun ends the others); rank 0 then says which task each rank had in
// hand (set_signal_note). A task that does not come back within the deadline (a rank that hangs
// or died unseen) ends every rank at once with exit status 1, naming the rank and the task.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fr {

struct TaskSharing {
  std::string noun = "task";  // what a task is, for messages: "frame", "band"
  // Results held by rank 0 ahead of the next one in order, at most (it hands out no task
  // further ahead); 0: no limit (results with no bytes, such as PNG frames the ranks write).
  size_t window = 0;
  // A task not back after this many seconds ends the job; <= 0: no limit.
  double deadline_s = 0;
};

// "2 ranks": the ranks that render (all but rank 0), for reports.
std::string rendering_ranks_text();

// lead_tasks (or dismiss_ranks) on rank 0 and serve_tasks on the others make one job: each
// returns once every rank has been dismissed, so that one job's messages never mix with the
// next's.

// Rank 0: shares out `tasks` (task numbers, in the order their results are wanted) until every
// result is delivered, calling `deliver(task, bytes)` for each in that order, on this thread.
// Throws std::runtime_error naming the rank and task when a task failed there, or what
// `deliver` threw; the other ranks are dismissed with exit status 1 first.
void lead_tasks(const std::vector<int>& tasks, const TaskSharing& how,
                const std::function<void(int task, std::vector<uint8_t>& result)>& deliver);

// Rank 0, when the job ends before lead_tasks: dismisses every other rank with `exit_status`
// (0: there was nothing to do).
void dismiss_ranks(int exit_status);

// A rank's part of a job that failed, where another rank has said why (rank 0 for a task that
// failed anywhere): the command ends with exit_status and prints nothing more.
struct AlreadyReported : std::runtime_error {
  explicit AlreadyReported(int status)
      : std::runtime_error("already reported"), exit_status(status) {}
  int exit_status;
};

// Every other rank: does the tasks rank 0 hands out, `work(task)` returning the result's bytes,
// until dismissed. A task that throws is reported to rank 0 (the message of the exception).
// Returns when dismissed with 0; throws AlreadyReported when dismissed with another status.
void serve_tasks(const std::function<std::vector<uint8_t>(int task)>& work);

}  // namespace fr
