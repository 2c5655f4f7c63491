// The world of one process that a build without MPI has (host/mpi/mpi_world_single.cpp, compiled
// into this test in every build): one process, exactly as without a launcher, and a refusal to run
// as one of several copies that a launcher started, since each would render the whole job into
// the same files.
#include "mpi/mpi_world.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace fr {
namespace {

TEST(MpiSingle, WithoutALauncherItIsOneProcess) {
  unsetenv("OMPI_COMM_WORLD_SIZE");
  unsetenv("PMI_SIZE");
  int argc = 1;
  char name[] = "fractalis";
  char* args[] = {name, nullptr};
  char** argv = args;
  std::string problem;
  ASSERT_TRUE(start_mpi(&argc, &argv, &problem)) << problem;
  EXPECT_EQ(mpi_world().rank, 0);
  EXPECT_EQ(mpi_world().size, 1);
  EXPECT_FALSE(mpi_world().shared());
  EXPECT_EQ(gather_from_all_ranks(7), std::vector<int>{7});
  EXPECT_EQ(core_binding_problem(), "");
  wait_for_all_ranks();
  finish_mpi();
}

TEST(MpiSingle, OneOfSeveralCopiesRefusesToRun) {
  int argc = 1;
  char name[] = "fractalis";
  char* args[] = {name, nullptr};
  char** argv = args;
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    setenv(variable, "3", 1);
    std::string problem;
    EXPECT_FALSE(start_mpi(&argc, &argv, &problem)) << variable;
    EXPECT_NE(problem.find("built without MPI"), std::string::npos) << problem;
    EXPECT_NE(problem.find("started 3 copies"), std::string::npos) << problem;
    // A job of one copy is one process as before.
    setenv(variable, "1", 1);
    problem.clear();
    EXPECT_TRUE(start_mpi(&argc, &argv, &problem)) << problem;
    unsetenv(variable);
  }
  // Messages between ranks have nobody to go to.
  EXPECT_THROW(send_to_rank(1, 1, {}), std::logic_error);
  EXPECT_THROW(poll_any_rank(), std::logic_error);
}

}  // namespace
}  // namespace fr
