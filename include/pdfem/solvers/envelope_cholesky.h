// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_ENVELOPE_CHOLESKY_H
#define PDFEM_SOLVERS_ENVELOPE_CHOLESKY_H

#include <cstddef>
#include <vector>

namespace pdfem
{
  namespace Solvers
  {
    /**
     * Cholesky factorisation P A P^T = L L^T of a sparse symmetric positive
     * definite matrix A, with L kept by rows in the envelope (profile) of
     * P A P^T: row i from its first nonzero column f_i to the diagonal, in
     * one contiguous piece. P is a reverse Cuthill-McKee order, which keeps
     * the envelope small. The factorisation fills in only inside the
     * envelope (George and Liu, Computer Solution of Large Sparse Positive
     * Definite Systems, 1981, theorem 4.1.1), so L needs no more storage
     * than the envelope of P A P^T.
     *
     * Both triangular solves run over contiguous pieces of L and of the
     * vector (a dot product per row forwards, an axpy per row backwards),
     * which the compiler vectorises; a general sparse solve (KLU's) follows
     * index lists instead. This is the coarse solve of the AMG hierarchies
     * (initialize_amg_with_envelope_coarse_solve()): a few thousand unknowns,
     * solved once per preconditioner application.
     *
     * @tparam Number the type of the stored factors: double, or float for
     * half the memory traffic of a solve. The factorisation is computed in
     * double either way and rounded once; the solves accumulate in double.
     */
    template <typename Number>
    class EnvelopeCholesky
    {
    public:
      /**
       * Factorise the n x n symmetric matrix given by compressed rows
       * (@p row_starts of n + 1 entries, @p columns, @p values; both
       * triangles present). Returns false, and keeps no factors, if the
       * factorisation would take more than @p max_operations multiply-adds
       * (bounded by sum_i w_i (w_i + 1) / 2 over the envelope's row widths
       * w_i, checked before any work), if A is not symmetric (in its
       * pattern, or in a value by more than 1e-10 of the largest diagonal
       * entry), or if a pivot is not positive (below 1e-14 of the largest
       * diagonal entry): A is not (numerically) positive definite.
       */
      bool
      factorize(std::size_t   n,
                const int    *row_starts,
                const int    *columns,
                const double *values,
                double        max_operations);

      /// x = A^{-1} b; @p x and @p b may be the same array. Uses a
      /// workspace of the object: not for concurrent calls.
      void
      solve(const double *b, double *x) const;

      /// Rows of A (0 before a successful factorize()).
      std::size_t
      size() const
      {
        return inverse_diagonal.size();
      }

      /// Entries of L below the diagonal.
      std::size_t
      n_envelope_entries() const
      {
        return factors.size();
      }

      /// Bytes of the factors, the order and the workspace.
      std::size_t
      memory_consumption() const;

    private:
      /// Row i of L below the diagonal: factors[row_start[i] ...
      /// row_start[i + 1]), columns first_column[i] ... i - 1.
      std::vector<std::size_t>  row_start;
      std::vector<unsigned int> first_column;
      std::vector<Number>       factors;
      /// 1 / L_ii.
      std::vector<double> inverse_diagonal;
      /// position[k]: the row of P A P^T of row k of A.
      std::vector<unsigned int>   position;
      mutable std::vector<double> work;
    };
  } // namespace Solvers
} // namespace pdfem

#endif
