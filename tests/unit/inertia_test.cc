// SPDX-License-Identifier: LGPL-2.1-or-later
// compute_inertia (MUMPS LDL^T, Sylvester's law of inertia): the number of
// negative eigenvalues of symmetric matrices known analytically (shifted 1D
// Laplacians), by a dense LAPACK eigenvalue computation and by BandedLDLT,
// with the rows distributed over the ranks in three ways; singular matrices
// are flagged. ctest runs these on one rank (unit.Inertia.*) and on two
// (unit.np2.Inertia).
#include <pdfem/solvers/banded_ldlt.h>
#include <pdfem/solvers/inertia.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <utility>

#include <gtest/gtest.h>

namespace
{
  using namespace dealii;
  using pdfem::Solvers::compute_inertia;
  using pdfem::Solvers::Inertia;

  /// A symmetric n x n matrix by its entries (both triangles), the same on
  /// every rank.
  struct Symmetric
  {
    explicit Symmetric(const unsigned int n)
      : n(n)
    {}
    void
    add(const unsigned int i, const unsigned int j, const double v)
    {
      entries[{i, j}] += v;
      if (i != j)
        entries[{j, i}] += v;
    }
    unsigned int                                            n;
    std::map<std::pair<unsigned int, unsigned int>, double> entries;
  };

  /// How the rows are spread over the ranks.
  enum class Rows
  {
    blocks,      // contiguous halves
    interleaved, // row i on rank i % n_ranks
    first_rank   // all on rank 0, none elsewhere
  };

  IndexSet
  owned_rows(const unsigned int n, const Rows rows)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    IndexSet owned(n);
    if (rows == Rows::blocks)
      owned.add_range(std::uint64_t(n) * rank / n_ranks,
                      std::uint64_t(n) * (rank + 1) / n_ranks);
    else if (rows == Rows::interleaved)
      for (unsigned int i = rank; i < n; i += n_ranks)
        owned.add_index(i);
    else if (rank == 0)
      owned.add_range(0, n);
    owned.compress();
    return owned;
  }

  /// @p S as a Trilinos matrix with the rows spread as @p rows says.
  void
  distribute(const Symmetric                &S,
             const Rows                      rows,
             TrilinosWrappers::SparseMatrix &A)
  {
    const IndexSet                    owned = owned_rows(S.n, rows);
    TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
    for (const auto &[ij, v] : S.entries)
      if (owned.is_element(ij.first))
        pattern.add(ij.first, ij.second);
    pattern.compress();
    A.reinit(pattern);
    for (const auto &[ij, v] : S.entries)
      if (owned.is_element(ij.first))
        A.set(ij.first, ij.second, v);
    A.compress(VectorOperation::insert);
  }

  Inertia
  inertia(const Symmetric &S, const Rows rows)
  {
    TrilinosWrappers::SparseMatrix A;
    distribute(S, rows, A);
    const Inertia result = compute_inertia(A);
    // Every rank has the same answer.
    EXPECT_EQ(Utilities::MPI::max(result.n_negative, MPI_COMM_WORLD),
              Utilities::MPI::min(result.n_negative, MPI_COMM_WORLD));
    EXPECT_EQ(Utilities::MPI::max(result.n_null, MPI_COMM_WORLD),
              Utilities::MPI::min(result.n_null, MPI_COMM_WORLD));
    EXPECT_EQ(result.n_rows, S.n);
    return result;
  }

  /// The negative eigenvalues by LAPACK (dense, computed on every rank) and
  /// the smallest |eigenvalue|.
  std::pair<std::size_t, double>
  lapack_negative(const Symmetric &S)
  {
    LAPACKFullMatrix<double> F(S.n, S.n);
    for (const auto &[ij, v] : S.entries)
      F(ij.first, ij.second) = v;
    F.compute_eigenvalues();
    std::size_t negative = 0;
    double      smallest = 1e300;
    for (unsigned int i = 0; i < S.n; ++i)
      {
        const double lambda = F.eigenvalue(i).real();
        negative += lambda < 0.;
        smallest = std::min(smallest, std::abs(lambda));
      }
    return {negative, smallest};
  }

  /// The negative pivots of BandedLDLT (no pivoting); -1 if a pivot is 0.
  long
  banded_negative(const Symmetric &S)
  {
    unsigned int bandwidth = 0;
    for (const auto &[ij, v] : S.entries)
      bandwidth = std::max(bandwidth, ij.first - std::min(ij.first, ij.second));
    pdfem::Solvers::BandedLDLT K;
    K.reinit(S.n, bandwidth);
    for (const auto &[ij, v] : S.entries)
      K.add(ij.first, ij.second, v);
    return K.factorize() ? long(K.n_negative_pivots()) : -1;
  }

  /// tridiag(-1, 2, -1) - sigma I: eigenvalues 2 - 2 cos(k pi / (n + 1)) -
  /// sigma, k = 1..n. With @p neumann the end diagonals are 1 (the pure
  /// Neumann Laplacian): eigenvalues 2 - 2 cos(k pi / n) - sigma, k = 0..n-1.
  Symmetric
  laplacian_1d(const unsigned int n, const double sigma, bool neumann = false)
  {
    Symmetric S(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const bool end = i == 0 || i + 1 == n;
        S.add(i, i, (neumann && end ? 1. : 2.) - sigma);
        if (i > 0)
          S.add(i, i - 1, -1.);
      }
    return S;
  }

  /// Uniform in [-1, 1) from the raw 32-bit draws: the same everywhere.
  double
  uniform(std::mt19937 &gen)
  {
    return gen() / 2147483648. - 1.;
  }

  constexpr Rows all_rows[] = {Rows::blocks,
                               Rows::interleaved,
                               Rows::first_rank};

  TEST(Inertia, ShiftedLaplacian1DHasTheAnalyticCount)
  {
    const unsigned int n = 300;
    for (const double sigma : {-0.5, 0.01, 0.3, 1.3, 2.9, 3.97, 4.5})
      {
        std::size_t expected = 0;
        double      gap      = 1e300;
        for (unsigned int k = 1; k <= n; ++k)
          {
            const double lambda =
              2. - 2. * std::cos(k * M_PI / (n + 1)) - sigma;
            expected += lambda < 0.;
            gap = std::min(gap, std::abs(lambda));
          }
        ASSERT_GT(gap, 1e-5)
          << "sigma = " << sigma << " is too near an eigenvalue";
        const Symmetric S = laplacian_1d(n, sigma);
        EXPECT_EQ(banded_negative(S), long(expected)) << "sigma = " << sigma;
        for (const Rows rows : all_rows)
          {
            const Inertia result = inertia(S, rows);
            EXPECT_EQ(result.n_negative, expected) << "sigma = " << sigma;
            EXPECT_EQ(result.n_null, 0u) << "sigma = " << sigma;
            EXPECT_FALSE(result.singular) << "sigma = " << sigma;
            EXPECT_EQ(result.positive_definite(), expected == 0);
            EXPECT_EQ(result.n_positive(), n - expected);
          }
      }
  }

  TEST(Inertia, PerturbedLaplacian2DMatchesLapackAndBandedLDLT)
  {
    // The 5-point Laplacian on a 14 x 14 grid, every coupling within the
    // band (|i - j| <= 14) perturbed at random, shifted by sigma.
    const unsigned int m = 14, n = m * m;
    std::mt19937       gen(2024);
    Symmetric          base(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        base.add(i, i, 4. + 0.5 * uniform(gen));
        if (i % m > 0)
          base.add(i, i - 1, -1.);
        if (i >= m)
          base.add(i, i - m, -1.);
        for (unsigned int j = i >= m ? i - m : 0; j < i; ++j)
          if (gen() % 4 == 0)
            base.add(i, j, 0.3 * uniform(gen));
      }
    for (const double sigma : {0., 1.5, 3.3, 6.})
      {
        Symmetric S = base;
        for (unsigned int i = 0; i < n; ++i)
          S.add(i, i, -sigma);
        const auto [expected, smallest] = lapack_negative(S);
        ASSERT_GT(smallest, 1e-6) << "sigma = " << sigma;
        EXPECT_EQ(banded_negative(S), long(expected)) << "sigma = " << sigma;
        for (const Rows rows : all_rows)
          {
            const Inertia result = inertia(S, rows);
            EXPECT_EQ(result.n_negative, expected) << "sigma = " << sigma;
            EXPECT_FALSE(result.singular) << "sigma = " << sigma;
          }
      }
  }

  TEST(Inertia, SaddlePointNeedsTwoByTwoPivots)
  {
    // [K B^T; B 0] with K positive definite (n x n) and B of full row rank
    // (c x n) has exactly c negative eigenvalues. The constraints come
    // first: a zero diagonal entry in the first row, which a factorisation
    // without pivoting cannot take (BandedLDLT stops there).
    const unsigned int n = 80, c = 25;
    std::mt19937       gen(7);
    Symmetric          S(n + c);
    for (unsigned int i = 0; i < n; ++i)
      {
        S.add(c + i, c + i, 2.);
        if (i > 0)
          S.add(c + i, c + i - 1, -1.);
      }
    for (unsigned int r = 0; r < c; ++r)
      {
        // B(r, 3r) = 1 gives full rank; a few random entries besides.
        S.add(c + 3 * r, r, 1.);
        for (unsigned int k = 0; k < 3; ++k)
          S.add(c + gen() % n, r, 0.5 * uniform(gen));
      }
    const auto [expected, smallest] = lapack_negative(S);
    ASSERT_EQ(expected, std::size_t(c));
    ASSERT_GT(smallest, 1e-6);
    EXPECT_EQ(banded_negative(S), -1);
    for (const Rows rows : all_rows)
      {
        const Inertia result = inertia(S, rows);
        EXPECT_EQ(result.n_negative, std::size_t(c));
        EXPECT_EQ(result.n_positive(), std::size_t(n));
        EXPECT_FALSE(result.singular);
      }
  }

  TEST(Inertia, SingularMatricesAreFlagged)
  {
    const unsigned int n = 240;
    for (const Rows rows : all_rows)
      {
        // The pure Neumann Laplacian: one zero eigenvalue (constants).
        Inertia result = inertia(laplacian_1d(n, 0., true), rows);
        EXPECT_TRUE(result.singular);
        EXPECT_EQ(result.n_null, 1u);
        EXPECT_EQ(result.n_negative, 0u);
        EXPECT_FALSE(result.positive_definite());

        // Shifted by 1: 2 - 2 cos(k pi / n) - 1 is 0 for k = n / 3 exactly
        // (every entry is exact), negative for k < n / 3.
        result = inertia(laplacian_1d(n, 1., true), rows);
        EXPECT_TRUE(result.singular);
        EXPECT_EQ(result.n_null, 1u);
        EXPECT_EQ(result.n_negative, std::size_t(n / 3));

        // A zero row and column, stored (explicit zeros) or not stored.
        for (const bool stored : {true, false})
          {
            Symmetric S = laplacian_1d(n, 0.);
            for (auto it = S.entries.begin(); it != S.entries.end();)
              if (it->first.first == 17 || it->first.second == 17)
                {
                  if (stored)
                    (it++)->second = 0.;
                  else
                    it = S.entries.erase(it);
                }
              else
                ++it;
            result = inertia(S, rows);
            EXPECT_TRUE(result.singular) << "stored: " << stored;
            EXPECT_EQ(result.n_null, 1u) << "stored: " << stored;
            EXPECT_EQ(result.n_negative, 0u) << "stored: " << stored;
          }

        // Rank deficient: G^T G - G'^T G' with G (6 x 40), G' (4 x 40):
        // rank 10, six positive and four negative eigenvalues, 30 zero.
        std::mt19937 gen(11);
        Symmetric    S(40);
        for (unsigned int r = 0; r < 10; ++r)
          {
            std::vector<double> g(40);
            for (double &x : g)
              x = uniform(gen);
            const double sign = r < 6 ? 1. : -1.;
            for (unsigned int i = 0; i < 40; ++i)
              for (unsigned int j = 0; j <= i; ++j)
                S.add(i, j, sign * g[i] * g[j]);
          }
        result = inertia(S, rows);
        EXPECT_TRUE(result.singular);
        EXPECT_EQ(result.n_null, 30u);
        EXPECT_EQ(result.n_negative, 4u);
      }
  }
} // namespace
