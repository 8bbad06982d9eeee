// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_ML_COARSE_SOLVE_H
#define PDFEM_SOLVERS_ML_COARSE_SOLVE_H

namespace dealii
{
  namespace TrilinosWrappers
  {
    class PreconditionAMG;
  }
} // namespace dealii

namespace pdfem
{
  namespace Solvers
  {
    /**
     * Replace the direct solve on the coarsest level of an ML hierarchy
     * (Amesos-KLU, deal.II's default) by an EnvelopeCholesky with factors in
     * single precision. Done only where it applies: one process, a coarsest
     * level solved by Amesos, a coarse matrix that is positive definite
     * and small enough to factorise in a few tens of milliseconds; otherwise
     * the hierarchy keeps its KLU solve. Returns whether the solve was
     * replaced.
     *
     * Why: KLU's solve follows index lists and copies through Amesos'
     * Epetra vectors; it was about half of a V-cycle on one thread while the
     * other thread waited. Per coarse solve, one rank, the same GMRES
     * iterations: the mixed-mode plate of doc/benchmarks/fracture.md 0.34 ->
     * 0.076 ms (1 068 solves per run), plateCrack FC1 0.44 -> 0.090 ms (927),
     * the 3D box 0.20 -> 0.031 ms.
     */
    bool
    use_envelope_coarse_solve(
      const dealii::TrilinosWrappers::PreconditionAMG &amg);
  } // namespace Solvers
} // namespace pdfem

#endif
