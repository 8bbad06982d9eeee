// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_MPI_STARTUP_H
#define PDFEM_BASE_MPI_STARTUP_H

namespace pdfem
{
  /**
   * Call before MPI is initialised. When the program was started without a
   * launcher (no mpirun/srun variables in the environment), it becomes an MPI
   * singleton, and Open MPI 4.1 then spends about 0.3 s of every run on
   * spawning its daemon and on probing the UCX network layer, which one
   * process never uses. This selects the shared-memory transports and an
   * isolated singleton instead (Open MPI's `ess_singleton_isolated`,
   * `pml = ob1`, `btl = self,vader`), which start in 0.02 s.
   *
   * Only variables the user has not set are set, and nothing is changed
   * under a launcher, so `mpirun -np N` runs are untouched.
   */
  void
  prepare_mpi_singleton_startup();
} // namespace pdfem

#endif
