// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_MPI_STARTUP_H
#define PDFEM_BASE_MPI_STARTUP_H

#include <string>

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
   * Every isolated singleton has the same job id, so by default they all
   * share the session directory `/tmp/ompi.<host>.<uid>/jf.0/1`: one
   * process removed it at its end while another, started at the same time,
   * was creating it, and that one failed in MPI_Init ("orte_session_dir
   * failed"; measured: 3 of 400 unit-test processes run six at a time,
   * the cause of the "flaky" unit test of issue 19). Each singleton
   * therefore gets its own session directory,
   * singleton_session_directory(), which Open MPI removes at MPI_Finalize.
   *
   * Only variables the user has not set are set, and nothing is changed
   * under a launcher, so `mpirun -np N` runs are untouched.
   */
  void
  prepare_mpi_singleton_startup();

  /**
   * The session directory of this process as an MPI singleton:
   * `$TMPDIR/ompi.pdfem.<uid>.<pid>` (`/tmp` without TMPDIR).
   */
  std::string
  singleton_session_directory();
} // namespace pdfem

#endif
