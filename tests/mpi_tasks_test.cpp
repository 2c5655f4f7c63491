// Sharing tasks among the ranks of a real MPI job (mpi/shared_tasks.hpp). CTest starts this
// program as `mpirun -np 3`: every rank runs every test, in the same order, rank 0 leading and
// the others serving.
#include "mpi/mpi_world.hpp"
#include "mpi/shared_tasks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <set>
#include <thread>

namespace fr {
namespace {

// A result that says which task it is and which rank made it: the task number `task` times
// (so sizes differ), then the rank.
std::vector<uint8_t> result_of(int task, int rank) {
  std::vector<uint8_t> bytes(static_cast<size_t>(task), static_cast<uint8_t>(task));
  bytes.push_back(static_cast<uint8_t>(rank));
  return bytes;
}

TEST(MpiTasks, TheJobHasThreeRanks) {
  ASSERT_EQ(mpi_world().size, 3) << "run under mpirun -np 3";
  const std::vector<int> all = gather_from_all_ranks(10 * mpi_world().rank + 1);
  EXPECT_EQ(all, (std::vector<int>{1, 11, 21}));
}

// Results come back in the list's order, whatever order the ranks finish them in, and both
// serving ranks get work.
TEST(MpiTasks, ResultsArriveInTheListsOrder) {
  const std::vector<int> tasks = {7, 3, 12, 0, 5, 9, 1, 14, 2, 8, 11, 4, 13, 6, 10};
  if (mpi_world().rank == 0) {
    std::vector<int> delivered;
    std::set<int> ranks;
    TaskSharing how;
    how.noun = "task";
    how.window = 2;
    how.deadline_s = 60;
    lead_tasks(tasks, how, [&](int task, std::vector<uint8_t>& bytes) {
      ASSERT_EQ(bytes.size(), static_cast<size_t>(task) + 1);
      EXPECT_TRUE(std::all_of(bytes.begin(), bytes.end() - 1,
                              [&](uint8_t b) { return b == static_cast<uint8_t>(task); }));
      ranks.insert(bytes.back());
      delivered.push_back(task);
    });
    EXPECT_EQ(delivered, tasks);
    EXPECT_EQ(ranks, (std::set<int>{1, 2}));
  } else {
    serve_tasks([](int task) {
      // Uneven times, different on the two ranks, so tasks finish out of order.
      const int ms = (task * (mpi_world().rank == 1 ? 7 : 3)) % 11;
      std::this_thread::sleep_for(std::chrono::milliseconds(ms));
      return result_of(task, mpi_world().rank);
    });
  }
}

// A task that throws on its rank: rank 0 names the rank, the task and the message, and the
// serving ranks end as already reported, with exit status 1.
TEST(MpiTasks, AFailedTaskIsReportedOnceWithItsRank) {
  const std::vector<int> tasks = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  if (mpi_world().rank == 0) {
    TaskSharing how;
    how.noun = "band";
    try {
      lead_tasks(tasks, how, [](int, std::vector<uint8_t>&) {});
      ADD_FAILURE() << "lead_tasks did not throw";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(", band 6: the DE fell over"), std::string::npos) << what;
      EXPECT_EQ(what.rfind("rank ", 0), 0u) << what;
    }
  } else {
    try {
      serve_tasks([](int task) {
        if (task == 6) throw std::runtime_error("the DE fell over");
        return result_of(task, mpi_world().rank);
      });
      ADD_FAILURE() << "serve_tasks returned after a failed task";
    } catch (const AlreadyReported& e) {
      EXPECT_EQ(e.exit_status, 1);
    }
  }
}

// What rank 0's writer throws ends the job the same way.
TEST(MpiTasks, AWriterFailureDismissesTheRanks) {
  const std::vector<int> tasks = {0, 1, 2, 3};
  if (mpi_world().rank == 0) {
    TaskSharing how;
    EXPECT_THROW(lead_tasks(tasks, how,
                            [](int task, std::vector<uint8_t>&) {
                              if (task == 1) throw std::runtime_error("disk full");
                            }),
                 std::runtime_error);
  } else {
    EXPECT_THROW(serve_tasks([](int task) { return result_of(task, mpi_world().rank); }),
                 AlreadyReported);
  }
}

// No tasks at all, and a job that ends before sharing: the ranks are dismissed with the status
// rank 0 gives.
TEST(MpiTasks, DismissedRanksEndWithRankZerosStatus) {
  for (const int status : {0, 2}) {
    if (mpi_world().rank == 0) {
      dismiss_ranks(status);
    } else if (status == 0) {
      EXPECT_NO_THROW(serve_tasks([](int) { return std::vector<uint8_t>(); }));
    } else {
      try {
        serve_tasks([](int) { return std::vector<uint8_t>(); });
        ADD_FAILURE() << "dismissed with " << status << " but returned";
      } catch (const AlreadyReported& e) {
        EXPECT_EQ(e.exit_status, status);
      }
    }
  }
  if (mpi_world().rank == 0) {
    lead_tasks({}, TaskSharing{}, [](int, std::vector<uint8_t>&) { ADD_FAILURE(); });
  } else {
    EXPECT_NO_THROW(serve_tasks([](int) {
      ADD_FAILURE() << "a task with none to do";
      return std::vector<uint8_t>();
    }));
  }
}

// A result of several MiB travels whole (and in order with the small ones).
TEST(MpiTasks, LargeResultsTravelWhole) {
  const std::vector<int> tasks = {0, 1, 2};
  const size_t big = size_t{24} << 20;
  if (mpi_world().rank == 0) {
    std::vector<size_t> sizes;
    TaskSharing how;
    how.window = 1;
    lead_tasks(tasks, how, [&](int task, std::vector<uint8_t>& bytes) {
      sizes.push_back(bytes.size());
      for (size_t i = 0; i < bytes.size(); i += 4099)
        ASSERT_EQ(bytes[i], static_cast<uint8_t>((i * 31 + static_cast<size_t>(task)) & 0xff));
    });
    EXPECT_EQ(sizes, (std::vector<size_t>{big, 5, big + 2}));
  } else {
    serve_tasks([&](int task) {
      const size_t n = task == 1 ? 5 : big + static_cast<size_t>(task);
      std::vector<uint8_t> bytes(n);
      for (size_t i = 0; i < n; ++i)
        bytes[i] = static_cast<uint8_t>((i * 31 + static_cast<size_t>(task)) & 0xff);
      return bytes;
    });
  }
}

}  // namespace
}  // namespace fr

int main(int argc, char** argv) {
  std::string problem;
  if (!fr::start_mpi(&argc, &argv, &problem)) {
    std::fprintf(stderr, "%s\n", problem.c_str());
    return 2;
  }
  ::testing::InitGoogleTest(&argc, argv);
  const int status = RUN_ALL_TESTS();
  fr::finish_mpi();
  return status;
}
