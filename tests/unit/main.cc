// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/mpi_startup.h>

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int
main(int argc, char **argv)
{
  pdfem::prepare_mpi_singleton_startup();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
