// SPDX-License-Identifier: LGPL-2.1-or-later
// MPI start-up without a launcher (pdfem::prepare_mpi_singleton_startup(),
// called by main.cc before MPI_Init): each singleton has its own Open MPI
// session directory. Isolated singletons all have job id 1, and when they
// shared /tmp/ompi.<host>.<uid>/jf.0/1, two processes started together
// could remove it under each other: MPI_Init failed in about 1 of 130
// processes run six at a time (the "flaky" unit test of issue 19).
#include <pdfem/base/mpi_startup.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace
{
  TEST(MPIStartup, SingletonHasItsOwnSessionDirectory)
  {
    if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr)
      GTEST_SKIP() << "started by mpirun: Open MPI's own session directory";
    const char *directory = std::getenv("OMPI_MCA_orte_top_session_dir");
    ASSERT_NE(directory, nullptr);
    EXPECT_EQ(directory, pdfem::singleton_session_directory());
    EXPECT_NE(std::string(directory).find("." + std::to_string(::getpid())),
              std::string::npos);
    // MPI is initialised (main.cc): Open MPI made the directory and uses it.
    EXPECT_TRUE(std::filesystem::is_directory(directory));
  }
} // namespace
