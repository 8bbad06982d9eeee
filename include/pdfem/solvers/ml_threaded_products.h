// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_ML_THREADED_PRODUCTS_H
#define PDFEM_SOLVERS_ML_THREADED_PRODUCTS_H

namespace dealii
{
  namespace TrilinosWrappers
  {
    class PreconditionAMG;
  }
} // namespace dealii

namespace pdfem
{
  class ThreadTeam;

  namespace Solvers
  {
    /**
     * Let the sparse products of an ML hierarchy run on the threads of
     * @p team: the finest level's Epetra matrix (the Chebyshev
     * sweeps and residuals) and ML's own CSR operators (restriction,
     * prolongation, coarse matrices). ML itself is single-threaded; on
     * plateCrack these products were about half of a V-cycle, the other half
     * being the coarse direct solve.
     *
     * Only operators whose product needs no communication are changed (an
     * Epetra matrix without importer or exporter, a CSR operator without
     * pre- or post-communication); the others keep ML's own product. Each
     * row's sum runs in the same order as in ML and Epetra, on one thread,
     * so the results do not depend on the number of threads. Returns the
     * number of operators changed (0 for a team of one).
     *
     * ML calls the products back with the operator alone, so the team is
     * kept in one place for the whole process: the last call's team serves
     * every hierarchy changed so far. It must outlive them.
     */
    unsigned int
    thread_ml_products(const dealii::TrilinosWrappers::PreconditionAMG &amg,
                       ThreadTeam                                      &team);
  } // namespace Solvers
} // namespace pdfem

#endif
