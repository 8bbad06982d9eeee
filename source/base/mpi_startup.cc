// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/mpi_startup.h>

#include <cstdlib>

namespace pdfem
{
  void
  prepare_mpi_singleton_startup()
  {
    // Variables set by mpirun/mpiexec (Open MPI, PMIx), MPICH's Hydra and
    // Slurm: any of them means a launcher started us.
    for (const char *launcher_variable : {"OMPI_COMM_WORLD_SIZE",
                                          "PMIX_RANK",
                                          "PMI_RANK",
                                          "PMI_SIZE",
                                          "SLURM_PROCID"})
      if (std::getenv(launcher_variable) != nullptr)
        return;
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self,vader", 0);
  }
} // namespace pdfem
