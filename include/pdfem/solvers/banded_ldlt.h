// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_BANDED_LDLT_H
#define PDFEM_SOLVERS_BANDED_LDLT_H

#include <cstddef>
#include <vector>

namespace pdfem
{
  namespace Solvers
  {
    /**
     * A symmetric band matrix (half bandwidth b: A(i, j) = 0 for |i-j| > b)
     * with an LDL^T factorisation without pivoting, O(n b^2). Besides
     * solving, the factorisation gives the inertia of A (Sylvester's law:
     * the number of negative pivots D_ii is the number of negative
     * eigenvalues), which is the stability check of a tangent (specs/001
     * §2.5: a converged state is stable iff the reduced tangent is positive
     * definite). A positive definite matrix (every stable state) is
     * factorised by LAPACK's blocked band Cholesky (dpbtrf), an indefinite
     * one by the LDL^T here. Meant for RNP systems of moderate size (a few
     * 10^4 unknowns with a bandwidth of a few hundred); serial.
     */
    class BandedLDLT
    {
    public:
      /// An n x n zero matrix with half bandwidth @p bandwidth.
      void
      reinit(std::size_t n, std::size_t bandwidth);

      /// Set every entry to zero (keeps the size); forgets the factors.
      void
      clear_values();

      /// A(i, j) += v for j <= i (the upper triangle is implied by
      /// symmetry; entries with j > i are ignored).
      void
      add(std::size_t i, std::size_t j, double v)
      {
        if (j <= i)
          band[i * (b + 1) + (j + b - i)] += v;
      }

      double
      operator()(std::size_t i, std::size_t j) const;

      /**
       * Factorise A = L D L^T. Returns false if a pivot is zero (relative to
       * the largest diagonal entry, 1e-13), i.e. A is (numerically)
       * singular; the inertia is then still counted up to that pivot.
       */
      bool
      factorize();

      /// Solve A x = rhs with the factors; @p x holds rhs on entry.
      void
      solve(std::vector<double> &x) const;

      std::size_t
      size() const
      {
        return n;
      }
      std::size_t
      bandwidth() const
      {
        return b;
      }
      bool
      factorized() const
      {
        return is_factorized;
      }
      /// Negative pivots of the last factorisation: negative eigenvalues.
      std::size_t
      n_negative_pivots() const
      {
        return n_negative;
      }
      /// The pivot D_ii of smallest modulus relative to max |A_ii|.
      double
      smallest_relative_pivot() const
      {
        return smallest_pivot;
      }

    private:
      std::size_t         n = 0, b = 0;
      std::vector<double> band;    // row i: A(i, i-b .. i)
      std::vector<double> factors; // L (unit diagonal) below, D on it
      bool                is_factorized  = false;
      bool                is_cholesky    = false; // factors from LAPACK
      std::size_t         n_negative     = 0;
      double              smallest_pivot = 0.;
    };

    /**
     * A reverse Cuthill-McKee order of a graph given by adjacency lists:
     * order[k] = the vertex placed k-th. Keeps the bandwidth of a lattice's
     * matrix near its optimum whatever the input numbering.
     */
    std::vector<unsigned int>
    reverse_cuthill_mckee(
      const std::vector<std::vector<unsigned int>> &adjacency);
  } // namespace Solvers
} // namespace pdfem

#endif
