#include "mpi/shared_tasks.hpp"

#include "io/atomic_file.hpp"
#include "mpi/mpi_world.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstring>
#include <deque>
#include <map>
#include <optional>
#include <thread>

namespace fr {
namespace {

// Rank to rank 0: the outcome of the task it had (none on its first message) and a request for
// the next. Rank 0 to a rank: the next task, or a dismissal with an exit status.
constexpr int kTagDone = 1;
constexpr int kTagNext = 2;

enum class Outcome : uint8_t { FirstRequest = 0, Result = 1, Failed = 2 };

// A Done message: task (int64), outcome (uint8), then the result's bytes or the failure's text.
constexpr size_t kDoneHeader = 9;
// A Next message: task (int64, -1: dismissed) and the exit status (int32) of a dismissal.
constexpr size_t kNextSize = 12;

void put(std::vector<uint8_t>& out, size_t at, const void* value, size_t n) {
  std::memcpy(out.data() + at, value, n);
}
template <typename T>
T get(const std::vector<uint8_t>& in, size_t at) {
  T value{};
  if (in.size() >= at + sizeof(T)) std::memcpy(&value, in.data() + at, sizeof(T));
  return value;
}

std::vector<uint8_t> next_message(int64_t task, int32_t exit_status) {
  std::vector<uint8_t> m(kNextSize);
  put(m, 0, &task, 8);
  put(m, 8, &exit_status, 4);
  return m;
}

void send_done(int64_t task, Outcome outcome, const uint8_t* bytes, size_t n) {
  std::vector<uint8_t> m(kDoneHeader + n);
  put(m, 0, &task, 8);
  m[8] = static_cast<uint8_t>(outcome);
  if (n > 0) std::memcpy(m.data() + kDoneHeader, bytes, n);
  send_to_rank(0, kTagDone, m);
}

using Clock = std::chrono::steady_clock;

struct InHand {
  size_t index = 0;  // into the task list
  Clock::time_point since;
};

// What each rank has in hand, for the signal handler's last words.
void note_tasks_in_hand(const std::map<int, InHand>& in_hand, const std::vector<int>& tasks,
                        const std::string& noun) {
  if (in_hand.empty()) {
    set_signal_note("");
    return;
  }
  std::string note = "fractalis: the job ended while";
  const char* separator = " ";
  for (const auto& [rank, hand] : in_hand) {
    note += separator + std::string("rank ") + std::to_string(rank) + " had " + noun + " " +
            std::to_string(tasks[hand.index]);
    separator = ", ";
  }
  set_signal_note(note);
}

// Rank 0's side of a shared job, one step at a time (lead_tasks runs the steps in a loop).
class TaskLeader {
 public:
  using Deliver = std::function<void(int task, std::vector<uint8_t>& result)>;
  TaskLeader(const std::vector<int>& tasks, const TaskSharing& how, const Deliver& deliver)
      : tasks_(tasks), how_(how), deliver_(deliver) {}

  // Every rank has been dismissed.
  bool done() const { return dismissed_ == mpi_world().size - 1; }
  const std::optional<std::string>& failure() const { return failure_; }

  // Takes one message, if one came: a rank's result or failure, and its request for more.
  bool take_message() {
    auto m = poll_any_rank();
    if (!m) return false;
    const auto outcome = static_cast<Outcome>(get<uint8_t>(m->bytes, 8));
    const auto hand = in_hand_.find(m->from);
    if (outcome != Outcome::FirstRequest && hand != in_hand_.end()) {
      if (outcome == Outcome::Result) {
        m->bytes.erase(m->bytes.begin(), m->bytes.begin() + kDoneHeader);
        results_.emplace(hand->second.index, std::move(m->bytes));
      } else if (!failure_) {
        failure_ = "rank " + std::to_string(m->from) + ", " + how_.noun + " " +
                   std::to_string(tasks_[hand->second.index]) + ": " +
                   std::string(m->bytes.begin() + kDoneHeader, m->bytes.end());
      }
      in_hand_.erase(hand);
    }
    waiting_.push_back(m->from);
    return true;
  }

  // Delivers the results that are next in order.
  bool deliver_in_order() {
    bool delivered = false;
    while (!failure_ && !results_.empty() && results_.begin()->first == written_) {
      try {
        deliver_(tasks_[written_], results_.begin()->second);
      } catch (const std::exception& e) {
        failure_ = e.what();
      }
      results_.erase(results_.begin());
      ++written_;
      delivered = true;
    }
    return delivered;
  }

  // Hands tasks to the ranks that asked, within the window; dismisses them once every result has
  // been delivered (or the job failed).
  bool hand_out() {
    bool handed = false;
    while (!waiting_.empty()) {
      const int rank = waiting_.front();
      if (failure_ || written_ == tasks_.size()) {
        send_to_rank(rank, kTagNext, next_message(-1, failure_ ? 1 : 0));
        ++dismissed_;
      } else if (next_ == tasks_.size()) {
        // None left to hand out, but results still to deliver: the rank is dismissed once they
        // are, so that a writer's failure reaches it too (dismissed now, it would end with 0).
        break;
      } else if (how_.window == 0 || next_ < written_ + how_.window) {
        send_to_rank(rank, kTagNext, next_message(tasks_[next_], 0));
        in_hand_[rank] = {next_++, Clock::now()};
      } else {
        break;  // the window is full: results in order come first
      }
      waiting_.pop_front();
      handed = true;
    }
    return handed;
  }

  // What each rank has in hand, for the signal handler's last words.
  void note_in_hand() const { note_tasks_in_hand(in_hand_, tasks_, how_.noun); }

  // Ends the job when a task has been out longer than the deadline.
  void check_deadlines() const {
    if (how_.deadline_s <= 0) return;
    for (const auto& [rank, hand] : in_hand_) {
      const double held_s = std::chrono::duration<double>(Clock::now() - hand.since).count();
      if (held_s <= how_.deadline_s) continue;
      spdlog::error(
          "rank {} has not finished {} {} after {:.0f} s: it died or hangs; ending the job", rank,
          how_.noun, tasks_[hand.index], held_s);
      set_signal_note("");
      abort_all_ranks(1);
    }
  }

 private:
  const std::vector<int>& tasks_;
  const TaskSharing& how_;
  const Deliver& deliver_;
  size_t next_ = 0;     // the next task to hand out
  size_t written_ = 0;  // the next task to deliver
  std::map<size_t, std::vector<uint8_t>> results_;
  std::map<int, InHand> in_hand_;
  std::deque<int> waiting_;  // ranks that asked for a task and have none yet
  int dismissed_ = 0;
  std::optional<std::string> failure_;
};

}  // namespace

void lead_tasks(const std::vector<int>& tasks, const TaskSharing& how,
                const std::function<void(int task, std::vector<uint8_t>& result)>& deliver) {
  TaskLeader leader(tasks, how, deliver);
  while (!leader.done()) {
    // Hand out before delivering: a rank that asked renders while rank 0 encodes.
    const bool took = leader.take_message();
    const bool handed = leader.hand_out();
    const bool delivered = leader.deliver_in_order();
    if (took || handed) leader.note_in_hand();
    leader.check_deadlines();
    // Rank 0 waits by sleeping, not spinning: on a machine it shares with rendering ranks, a
    // spinning leader would take a core from them. A millisecond is nothing to a frame.
    if (!took && !delivered && !handed) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  set_signal_note("");
  // Every rank leaves the job together: a rank dismissed early must not start on whatever comes
  // next while rank 0 still listens for this job's results.
  wait_for_all_ranks();
  if (leader.failure()) throw std::runtime_error(*leader.failure());
}

void dismiss_ranks(int exit_status) {
  for (int dismissed = 0; dismissed < mpi_world().size - 1;) {
    if (const auto m = poll_any_rank()) {
      send_to_rank(m->from, kTagNext, next_message(-1, exit_status));
      ++dismissed;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  wait_for_all_ranks();
}

void serve_tasks(const std::function<std::vector<uint8_t>(int task)>& work) {
  if (const std::string problem = core_binding_problem(); !problem.empty())
    spdlog::warn("{}", problem);
  send_done(-1, Outcome::FirstRequest, nullptr, 0);
  for (;;) {
    const RankMessage m = receive_from_rank(0);
    const auto task = get<int64_t>(m.bytes, 0);
    if (task < 0) {
      wait_for_all_ranks();  // with rank 0, once every rank is dismissed (lead_tasks)
      const auto status = get<int32_t>(m.bytes, 8);
      if (status != 0) throw AlreadyReported(status);
      return;
    }
    try {
      const std::vector<uint8_t> result = work(static_cast<int>(task));
      send_done(task, Outcome::Result, result.data(), result.size());
    } catch (const std::exception& e) {
      const std::string what = e.what();
      send_done(task, Outcome::Failed, reinterpret_cast<const uint8_t*>(what.data()), what.size());
    }
  }
}

std::string rendering_ranks_text() {
  const int n = mpi_world().size - 1;
  return std::to_string(n) + (n == 1 ? " rank" : " ranks");
}

}  // namespace fr
