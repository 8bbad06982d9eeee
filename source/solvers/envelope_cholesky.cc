// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/solvers/banded_ldlt.h>
#include <pdfem/solvers/envelope_cholesky.h>

#include <algorithm>
#include <cmath>

namespace pdfem
{
  namespace Solvers
  {
    namespace
    {
      /// sum_k a[k] b[k] for k < n, in the same order on every call (the
      /// reduction is split into the vector lanes fixed at compile time).
      template <typename NumberA>
      double
      dot(const NumberA *a, const double *b, const std::size_t n)
      {
        double sum = 0.;
#pragma omp simd reduction(+ : sum)
        for (std::size_t k = 0; k < n; ++k)
          sum += double(a[k]) * b[k];
        return sum;
      }

      /// Relative to the largest diagonal entry: Galerkin coarse matrices
      /// R A P of a symmetric A are symmetric up to rounding.
      constexpr double symmetry_tolerance = 1e-10;
    } // namespace

    template <typename Number>
    bool
    EnvelopeCholesky<Number>::factorize(const std::size_t n,
                                        const int        *row_starts,
                                        const int        *columns,
                                        const double     *values,
                                        const double      max_operations)
    {
      row_start.clear();
      first_column.clear();
      factors.clear();
      inverse_diagonal.clear();
      position.clear();

      std::vector<std::vector<unsigned int>> adjacency(n);
      for (std::size_t i = 0; i < n; ++i)
        for (int k = row_starts[i]; k < row_starts[i + 1]; ++k)
          if (static_cast<std::size_t>(columns[k]) != i)
            adjacency[i].push_back(columns[k]);
      const std::vector<unsigned int> order = reverse_cuthill_mckee(adjacency);
      std::vector<unsigned int>       new_position(n);
      for (std::size_t p = 0; p < n; ++p)
        new_position[order[p]] = p;

      // The envelope of P A P^T, row by row.
      std::vector<unsigned int> first(n);
      std::vector<std::size_t>  start(n + 1, 0);
      double                    operations = 0.;
      for (std::size_t p = 0; p < n; ++p)
        {
          unsigned int f = p;
          for (const unsigned int j : adjacency[order[p]])
            f = std::min(f, new_position[j]);
          first[p]     = f;
          start[p + 1] = start[p] + (p - f);
          operations += 0.5 * double(p - f) * double(p - f + 1);
        }
      if (operations > max_operations)
        return false;

      // Row p holds (P A P^T)(p, f_p .. p - 1), then L's row in place.
      std::vector<double> L(start[n], 0.), diagonal(n, 0.);
      double              largest_diagonal = 0.;
      for (std::size_t p = 0; p < n; ++p)
        {
          const std::size_t row = order[p];
          for (int k = row_starts[row]; k < row_starts[row + 1]; ++k)
            {
              const unsigned int q = new_position[columns[k]];
              if (q == p)
                diagonal[p] += values[k];
              else if (q < p)
                L[start[p] + (q - first[p])] += values[k];
            }
          largest_diagonal = std::max(largest_diagonal, diagonal[p]);
        }
      // Only the lower triangle is factorised, so an unsymmetric matrix is
      // refused rather than replaced by its lower half: the upper triangle,
      // transposed, must equal it up to rounding. An entry whose transpose
      // is absent (outside the envelope) must be a rounding zero; ML's
      // R A P keeps such entries in one row only (plateCrack FC1: -2.8e-8
      // against diagonal entries of 8e9).
      {
        const double        tolerance = symmetry_tolerance * largest_diagonal;
        std::vector<double> upper(start[n], 0.);
        for (std::size_t p = 0; p < n; ++p)
          for (int k = row_starts[order[p]]; k < row_starts[order[p] + 1]; ++k)
            {
              const unsigned int q = new_position[columns[k]];
              if (q <= p)
                continue;
              if (p >= first[q])
                upper[start[q] + (p - first[q])] += values[k];
              else if (!(std::abs(values[k]) <= tolerance))
                return false;
            }
        for (std::size_t k = 0; k < upper.size(); ++k)
          if (!(std::abs(upper[k] - L[k]) <= tolerance))
            return false;
      }
      for (std::size_t p = 0; p < n; ++p)
        {
          double *Lp = L.data() + start[p];
          for (std::size_t q = first[p]; q < p; ++q)
            {
              const std::size_t k0 = std::max(first[p], first[q]);
              Lp[q - first[p]] =
                (Lp[q - first[p]] - dot(Lp + (k0 - first[p]),
                                        L.data() + start[q] + (k0 - first[q]),
                                        q - k0)) *
                diagonal[q];
            }
          const double pivot =
            diagonal[p] -
            dot(Lp, static_cast<const double *>(Lp), p - first[p]);
          if (!(pivot > 1e-14 * largest_diagonal))
            return false;
          diagonal[p] = 1. / std::sqrt(pivot); // from here on 1 / L_pp
        }

      row_start    = std::move(start);
      first_column = std::move(first);
      factors.assign(L.begin(), L.end());
      inverse_diagonal = std::move(diagonal);
      position         = std::move(new_position);
      work.resize(n);
      return true;
    }

    template <typename Number>
    void
    EnvelopeCholesky<Number>::solve(const double *b, double *x) const
    {
      const std::size_t n = inverse_diagonal.size();
      double           *y = work.data();
      for (std::size_t k = 0; k < n; ++k)
        y[position[k]] = b[k];
      // L y = P b: one dot product per row.
      for (std::size_t p = 0; p < n; ++p)
        y[p] = (y[p] - dot(factors.data() + row_start[p],
                           y + first_column[p],
                           p - first_column[p])) *
               inverse_diagonal[p];
      // L^T z = y: row p of L scatters z_p into the rows above it.
      for (std::size_t p = n; p-- > 0;)
        {
          const double  zp         = y[p] * inverse_diagonal[p];
          const Number *Lp         = factors.data() + row_start[p];
          double       *out        = y + first_column[p];
          y[p]                     = zp;
          const std::size_t length = p - first_column[p];
#pragma omp simd
          for (std::size_t k = 0; k < length; ++k)
            out[k] -= double(Lp[k]) * zp;
        }
      for (std::size_t k = 0; k < n; ++k)
        x[k] = y[position[k]];
    }

    template <typename Number>
    std::size_t
    EnvelopeCholesky<Number>::memory_consumption() const
    {
      return row_start.size() * sizeof(std::size_t) +
             (first_column.size() + position.size()) * sizeof(unsigned int) +
             factors.size() * sizeof(Number) +
             (inverse_diagonal.size() + work.size()) * sizeof(double);
    }

    template class EnvelopeCholesky<double>;
    template class EnvelopeCholesky<float>;
  } // namespace Solvers
} // namespace pdfem
