// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_INERTIA_H
#define PDFEM_SOLVERS_INERTIA_H

#include <cstddef>
#include <limits>

namespace dealii
{
  namespace TrilinosWrappers
  {
    class SparseMatrix;
  }
} // namespace dealii

namespace pdfem
{
  namespace Solvers
  {
    /**
     * The inertia of a symmetric matrix A: how many of its eigenvalues are
     * negative, zero and positive. By Sylvester's law of inertia, A and
     * D = L^{-1} P A P^T L^{-T} have the same inertia for any nonsingular L
     * and permutation P, so an LDL^T factorisation (D block diagonal with 1x1
     * and 2x2 blocks) gives it by counting the negative eigenvalues of D.
     */
    struct Inertia
    {
      /// The order of A.
      std::size_t n_rows = 0;
      /// The number of negative eigenvalues: MUMPS's INFOG(12), the negative
      /// pivots of its LDL^T factorisation (SYM = 2).
      std::size_t n_negative = 0;
      /// The number of null pivots: MUMPS's INFOG(28) with null pivot
      /// detection on (ICNTL(24) = 1), i.e. pivot rows whose infinity norm
      /// fell below null_pivot_tolerance times that of the scaled and
      /// permuted matrix (CNTL(3)). Not counted in n_negative (a pivot is
      /// null or negative, not both).
      std::size_t n_null = 0;
      /// A is numerically singular: n_null > 0, or MUMPS stopped with
      /// INFOG(1) = -10, "numerically singular" (which null pivot detection
      /// should prevent; n_negative then counts the pivots before the stop).
      bool singular = false;
      /// The relative threshold of the null pivot detection (MUMPS CNTL(3)).
      double null_pivot_tolerance = 0.;
      /**
       * Smallest |pivot| / max |A_ii| (what BandedLDLT reports). MUMPS 5.5
       * does not return its pivots, so this is NaN: unknown. What is known
       * is the bound above: a matrix that is not singular had no pivot row
       * below null_pivot_tolerance.
       */
      double smallest_relative_pivot = std::numeric_limits<double>::quiet_NaN();

      /// The number of positive eigenvalues.
      std::size_t
      n_positive() const
      {
        return n_rows - n_negative - n_null;
      }
      /// No negative and no zero eigenvalue (a stable state's tangent).
      bool
      positive_definite() const
      {
        return !singular && n_negative == 0;
      }
    };

    /**
     * The inertia of the symmetric matrix @p A, distributed over the ranks
     * of its communicator in any way (each rank's locally owned rows), by
     * a parallel LDL^T factorisation with MUMPS (called directly, not
     * through Amesos: Amesos_Mumps of Trilinos 13.2 always factorises with
     * SYM = 0, unsymmetric LU, whatever its "MatrixProperty", and its
     * INFOG(12) then counts off-diagonal pivots).
     *
     * MUMPS is run with SYM = 2 (general symmetric: 1x1 and 2x2 pivots;
     * SYM = 1 is for positive definite matrices only), the matrix given
     * distributed (ICNTL(18) = 3), the root node factorised without
     * ScaLAPACK (ICNTL(13) = 1: the MUMPS 5.5 user guide says INFOG(12)
     * leaves out the pivots of a root factorised by ScaLAPACK, which only
     * happens on more than one rank) and null pivot detection on
     * (ICNTL(24) = 1, CNTL(3) = @p null_pivot_tolerance).
     * The number of negative eigenvalues is INFOG(12) (Sylvester's law of
     * inertia), the number of zero ones INFOG(28).
     *
     * The null pivot test is on whole pivot rows, not on the size of a
     * pivot: an exactly singular matrix leaves rows of rounding noise,
     * which the default tolerance catches (measured: 2D Laplacians of 57k
     * and 160k unknowns with one or three zero eigenvalues, on 1 and 2
     * ranks; 1e-12 missed some of them at 160k), while a nonsingular 2D
     * Laplacian shifted to have an eigenvalue of 1e-12 |A| was neither
     * flagged nor miscounted (a tolerance of 1e-6 did flag it). An exactly
     * singular matrix may still, rarely, show one of its zero eigenvalues as a
     * tiny pivot of either sign instead of a null one; it is flagged singular
     * as long as one null pivot is found.
     *
     * Only the lower triangle of A (column <= row) is read: the upper one is
     * taken to mirror it. The factors are discarded. Collective over the
     * matrix's communicator; every rank gets the same result. Throws
     * RunFailure if MUMPS fails for another reason than singularity (e.g.
     * out of memory).
     */
    Inertia
    compute_inertia(const dealii::TrilinosWrappers::SparseMatrix &A,
                    double null_pivot_tolerance = 1e-9);
  } // namespace Solvers
} // namespace pdfem

#endif
