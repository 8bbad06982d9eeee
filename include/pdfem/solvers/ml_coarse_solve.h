// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_ML_COARSE_SOLVE_H
#define PDFEM_SOLVERS_ML_COARSE_SOLVE_H

namespace dealii
{
  namespace TrilinosWrappers
  {
    class PreconditionAMG;
    class SparseMatrix;
  } // namespace TrilinosWrappers
} // namespace dealii

namespace Teuchos
{
  class ParameterList;
}

namespace pdfem
{
  namespace Solvers
  {
    /**
     * amg.initialize(matrix, list), with the direct solve on the coarsest
     * level done by an EnvelopeCholesky with factors in single precision
     * instead of ML's Amesos-KLU, where that applies: one process, a coarse
     * matrix that is symmetric positive definite and small enough to factorise
     * in a few tens of milliseconds. ML builds the hierarchy without a coarse
     * solve ('coarse: type' do-nothing), so that it factorises nothing
     * itself, and the envelope solve becomes the coarsest level's
     * post-smoother. Where the envelope does not apply, the hierarchy is
     * built again exactly as @p list asks (KLU by deal.II's default).
     * Returns whether the envelope solve is used.
     *
     * Why: KLU's solve follows index lists and copies through Amesos'
     * Epetra vectors; it was about half of a V-cycle, on one thread while
     * the other waited, and its factorisation about half of a hierarchy's
     * build. Per coarse solve, one rank, the same GMRES iterations: the
     * mixed-mode plate of doc/benchmarks/fracture.md 0.34 -> 0.076 ms
     * (1 068 solves per run), plateCrack FC1 0.44 -> 0.090 ms (927), the 3D
     * box 0.20 -> 0.031 ms; factorising the mixed-mode plate's 1 360-row
     * coarse matrix 1.5 ms against KLU's 5.7-10 ms.
     */
    bool
    initialize_amg_with_envelope_coarse_solve(
      dealii::TrilinosWrappers::PreconditionAMG    &amg,
      const dealii::TrilinosWrappers::SparseMatrix &matrix,
      Teuchos::ParameterList                        list);
  } // namespace Solvers
} // namespace pdfem

#endif
