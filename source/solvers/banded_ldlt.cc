// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/solvers/banded_ldlt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

extern "C"
{
  // LAPACK band Cholesky (OpenBLAS on Debian): 'U' storage with LDAB = b + 1
  // is exactly the row-wise lower band kept here.
  void
  dpbtrf_(const char *uplo,
          const int  *n,
          const int  *kd,
          double     *ab,
          const int  *ldab,
          int        *info);
  void
  dpbtrs_(const char   *uplo,
          const int    *n,
          const int    *kd,
          const int    *nrhs,
          const double *ab,
          const int    *ldab,
          double       *b,
          const int    *ldb,
          int          *info);
}

namespace pdfem
{
  namespace Solvers
  {
    void
    BandedLDLT::reinit(const std::size_t n_rows, const std::size_t bandwidth)
    {
      n = n_rows;
      b = std::min(bandwidth, n > 0 ? n - 1 : 0);
      band.assign(n * (b + 1), 0.);
      factors.clear();
      is_factorized = false;
    }

    void
    BandedLDLT::clear_values()
    {
      std::fill(band.begin(), band.end(), 0.);
      is_factorized = false;
    }

    double
    BandedLDLT::operator()(std::size_t i, std::size_t j) const
    {
      if (j > i)
        std::swap(i, j);
      if (i - j > b)
        return 0.;
      return band[i * (b + 1) + (j + b - i)];
    }

    bool
    BandedLDLT::factorize()
    {
      // Positive definite (every stable state): LAPACK's blocked Cholesky.
      // Otherwise LDL^T below, which also counts the negative pivots.
      if (n > 0)
        {
          factors       = band;
          const int  nn = n, kd = b, ldab = b + 1;
          int        info = 0;
          const char uplo = 'U';
          dpbtrf_(&uplo, &nn, &kd, factors.data(), &ldab, &info);
          if (info == 0)
            {
              double max_diagonal = 0.;
              double smallest     = std::numeric_limits<double>::infinity();
              for (std::size_t i = 0; i < n; ++i)
                {
                  max_diagonal =
                    std::max(max_diagonal, std::abs(band[i * (b + 1) + b]));
                  const double u = factors[i * (b + 1) + b];
                  smallest       = std::min(smallest, u * u);
                }
              smallest_pivot = max_diagonal > 0. ? smallest / max_diagonal : 0.;
              if (smallest_pivot > 1e-13)
                {
                  n_negative    = 0;
                  is_cholesky   = true;
                  is_factorized = true;
                  return true;
                }
            }
        }
      is_cholesky         = false;
      factors             = band;
      n_negative          = 0;
      smallest_pivot      = std::numeric_limits<double>::infinity();
      double max_diagonal = 0.;
      for (std::size_t i = 0; i < n; ++i)
        max_diagonal = std::max(max_diagonal, std::abs(band[i * (b + 1) + b]));
      const double        zero = 1e-13 * max_diagonal;
      const std::size_t   w    = b + 1;
      std::vector<double> t(w); // t[k - i + b] = L_ik D_k of the current row
      bool                ok = true;
      for (std::size_t i = 0; i < n; ++i)
        {
          double           *Li    = &factors[i * w]; // Li[j - i + b]
          const std::size_t first = i >= b ? i - b : 0;
          for (std::size_t j = first; j < i; ++j)
            {
              // s = A_ij - sum_{k = first .. j-1} L_ik D_k L_jk
              const double     *Lj  = &factors[j * w]; // Lj[k - j + b]
              const double     *a   = &t[first + b - i];
              const double     *c   = &Lj[first + b - j];
              const std::size_t len = j - first;
              // four partial sums: vectorised without reassociation flags
              double      s0 = 0., s1 = 0., s2 = 0., s3 = 0.;
              std::size_t k = 0;
              for (; k + 4 <= len; k += 4)
                {
                  s0 += a[k] * c[k];
                  s1 += a[k + 1] * c[k + 1];
                  s2 += a[k + 2] * c[k + 2];
                  s3 += a[k + 3] * c[k + 3];
                }
              for (; k < len; ++k)
                s0 += a[k] * c[k];
              const double s = Li[j + b - i] - ((s0 + s1) + (s2 + s3));
              t[j + b - i]   = s;                      // L_ij D_j
              Li[j + b - i]  = s / factors[j * w + b]; // L_ij
            }
          double d = Li[b];
          for (std::size_t j = first; j < i; ++j)
            d -= Li[j + b - i] * t[j + b - i];
          Li[b] = d;
          if (d < 0.)
            ++n_negative;
          smallest_pivot =
            std::min(smallest_pivot,
                     max_diagonal > 0. ? std::abs(d) / max_diagonal : 0.);
          if (!(std::abs(d) > zero))
            {
              ok = false;
              break;
            }
        }
      is_factorized = ok;
      return ok;
    }

    void
    BandedLDLT::solve(std::vector<double> &x) const
    {
      if (is_cholesky)
        {
          const int  nn = n, kd = b, ldab = b + 1, nrhs = 1, ldb = n;
          int        info = 0;
          const char uplo = 'U';
          dpbtrs_(&uplo,
                  &nn,
                  &kd,
                  &nrhs,
                  factors.data(),
                  &ldab,
                  x.data(),
                  &ldb,
                  &info);
          return;
        }
      const std::size_t w = b + 1;
      // L y = rhs
      for (std::size_t i = 0; i < n; ++i)
        {
          const std::size_t first = i >= b ? i - b : 0;
          double            s     = x[i];
          const double     *Li    = &factors[i * w];
          for (std::size_t j = first; j < i; ++j)
            s -= Li[j + b - i] * x[j];
          x[i] = s;
        }
      // D z = y
      for (std::size_t i = 0; i < n; ++i)
        x[i] /= factors[i * w + b];
      // L^T x = z
      for (std::size_t i = n; i-- > 0;)
        {
          const std::size_t first = i >= b ? i - b : 0;
          const double     *Li    = &factors[i * w];
          const double      xi    = x[i];
          for (std::size_t j = first; j < i; ++j)
            x[j] -= Li[j + b - i] * xi;
        }
    }

    std::vector<unsigned int>
    reverse_cuthill_mckee(
      const std::vector<std::vector<unsigned int>> &adjacency)
    {
      const std::size_t         n = adjacency.size();
      std::vector<unsigned int> order;
      order.reserve(n);
      std::vector<char>         seen(n, 0);
      std::vector<unsigned int> by_degree(n);
      std::iota(by_degree.begin(), by_degree.end(), 0u);
      std::stable_sort(by_degree.begin(),
                       by_degree.end(),
                       [&](unsigned int a, unsigned int c) {
                         return adjacency[a].size() < adjacency[c].size();
                       });
      std::vector<unsigned int> next;
      for (const unsigned int start : by_degree)
        {
          if (seen[start])
            continue;
          // one connected component, breadth first from a low-degree vertex
          std::size_t head = order.size();
          order.push_back(start);
          seen[start] = 1;
          while (head < order.size())
            {
              const unsigned int v = order[head++];
              next.clear();
              for (const unsigned int w : adjacency[v])
                if (!seen[w])
                  {
                    seen[w] = 1;
                    next.push_back(w);
                  }
              std::stable_sort(next.begin(),
                               next.end(),
                               [&](unsigned int a, unsigned int c) {
                                 return adjacency[a].size() <
                                        adjacency[c].size();
                               });
              order.insert(order.end(), next.begin(), next.end());
            }
        }
      std::reverse(order.begin(), order.end());
      return order;
    }
  } // namespace Solvers
} // namespace pdfem
