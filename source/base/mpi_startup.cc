// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/mpi_startup.h>

#include <cstdlib>
#include <string>

#include <unistd.h>

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
    setenv("OMPI_MCA_orte_top_session_dir",
           singleton_session_directory().c_str(),
           0);
  }

  std::string
  singleton_session_directory()
  {
    const char *tmp = std::getenv("TMPDIR");
    return std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") +
           "/ompi.pdfem." + std::to_string(::getuid()) + "." +
           std::to_string(::getpid());
  }
} // namespace pdfem
