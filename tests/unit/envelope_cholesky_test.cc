// SPDX-License-Identifier: LGPL-2.1-or-later
// EnvelopeCholesky: solves of shuffled sparse SPD matrices to rounding
// (double factors) and to single precision (float factors), the envelope
// kept small whatever the numbering, refusals of indefinite matrices and of
// costly factorisations. initialize_amg_with_envelope_coarse_solve: the ML
// V-cycle with the envelope coarse solve equals KLU's to single precision
// and repeats itself bit for bit; with an indefinite coarse matrix the
// hierarchy is KLU's, bit for bit.
#include <pdfem/solvers/envelope_cholesky.h>
#include <pdfem/solvers/ml_coarse_solve.h>

#include <deal.II/base/index_set.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <random>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <gtest/gtest.h>

namespace
{
  /// A matrix by compressed rows, both triangles.
  struct Csr
  {
    std::size_t         n = 0;
    std::vector<int>    starts{0}, columns;
    std::vector<double> values;

    std::vector<double>
    times(const std::vector<double> &x) const
    {
      std::vector<double> y(n, 0.);
      for (std::size_t i = 0; i < n; ++i)
        for (int k = starts[i]; k < starts[i + 1]; ++k)
          y[i] += values[k] * x[columns[k]];
      return y;
    }
  };

  /**
   * The 5-point Laplacian of an m x m grid plus @p shift on the diagonal
   * and random symmetric weights on the edges (each edge -w, w in [0.5, 2],
   * the diagonal the sum of its row's |w| plus the shift), its unknowns
   * numbered at random.
   */
  Csr
  shuffled_grid_matrix(const unsigned int m,
                       const double       shift,
                       const unsigned int seed)
  {
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> weight(0.5, 2.);
    std::vector<unsigned int>              label(m * m);
    std::iota(label.begin(), label.end(), 0u);
    std::shuffle(label.begin(), label.end(), gen);
    std::vector<std::map<int, double>> rows(m * m);
    const auto connect = [&](unsigned int a, unsigned int b) {
      const double w = weight(gen);
      rows[label[a]][label[b]] -= w;
      rows[label[b]][label[a]] -= w;
      rows[label[a]][label[a]] += w;
      rows[label[b]][label[b]] += w;
    };
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        {
          rows[label[i * m + j]][label[i * m + j]] += shift;
          if (i + 1 < m)
            connect(i * m + j, (i + 1) * m + j);
          if (j + 1 < m)
            connect(i * m + j, i * m + j + 1);
        }
    Csr A;
    A.n = m * m;
    for (const auto &row : rows)
      {
        for (const auto &[column, value] : row)
          {
            A.columns.push_back(column);
            A.values.push_back(value);
          }
        A.starts.push_back(A.columns.size());
      }
    return A;
  }

  template <typename Number>
  double
  relative_solve_error(const Csr &A, const unsigned int seed)
  {
    pdfem::Solvers::EnvelopeCholesky<Number> factors;
    EXPECT_TRUE(factors.factorize(
      A.n, A.starts.data(), A.columns.data(), A.values.data(), 1e12));
    std::mt19937                           gen(seed);
    std::uniform_real_distribution<double> value(-1., 1.);
    std::vector<double>                    x(A.n);
    for (double &v : x)
      v = value(gen);
    std::vector<double> solution = A.times(x);
    factors.solve(solution.data(), solution.data()); // in place
    double error = 0., norm = 0.;
    for (std::size_t i = 0; i < A.n; ++i)
      {
        error += (solution[i] - x[i]) * (solution[i] - x[i]);
        norm += x[i] * x[i];
      }
    return std::sqrt(error / norm);
  }

  TEST(EnvelopeCholesky, SolvesShuffledGridMatrices)
  {
    // Condition numbers about 1e2 (shift 1) and 1e4 (shift 1e-3).
    for (const double shift : {1., 1e-3})
      {
        const Csr A = shuffled_grid_matrix(30, shift, 3);
        EXPECT_LT(relative_solve_error<double>(A, 5), 1e-12) << shift;
        const double single = relative_solve_error<float>(A, 5);
        EXPECT_LT(single, shift == 1. ? 1e-6 : 1e-4) << shift;
        EXPECT_GT(single, 1e-12) << "float factors should round";
      }
  }

  TEST(EnvelopeCholesky, ReverseCuthillMcKeeKeepsTheEnvelopeSmall)
  {
    // Numbered at random the envelope is about n^2 / 3; after reverse
    // Cuthill-McKee each row reaches back about one grid line (m).
    const unsigned int                      m = 40;
    const Csr                               A = shuffled_grid_matrix(m, 1., 11);
    pdfem::Solvers::EnvelopeCholesky<float> factors;
    ASSERT_TRUE(factors.factorize(
      A.n, A.starts.data(), A.columns.data(), A.values.data(), 1e12));
    EXPECT_EQ(factors.size(), A.n);
    EXPECT_LT(factors.n_envelope_entries(), 2 * m * A.n);
    EXPECT_GT(factors.memory_consumption(),
              factors.n_envelope_entries() * sizeof(float));
  }

  TEST(EnvelopeCholesky, RefusesIndefiniteMatricesAndCostlyFactorisations)
  {
    // A negative shift below the smallest eigenvalue: indefinite.
    const Csr indefinite = shuffled_grid_matrix(10, -0.5, 2);
    pdfem::Solvers::EnvelopeCholesky<double> factors;
    EXPECT_FALSE(factors.factorize(indefinite.n,
                                   indefinite.starts.data(),
                                   indefinite.columns.data(),
                                   indefinite.values.data(),
                                   1e12));
    EXPECT_EQ(factors.size(), 0u);

    // Singular: the pure Laplacian (shift 0) has the constants as kernel.
    const Csr singular = shuffled_grid_matrix(10, 0., 2);
    EXPECT_FALSE(factors.factorize(singular.n,
                                   singular.starts.data(),
                                   singular.columns.data(),
                                   singular.values.data(),
                                   1e12));

    const Csr A = shuffled_grid_matrix(10, 1., 2);
    EXPECT_FALSE(factors.factorize(
      A.n, A.starts.data(), A.columns.data(), A.values.data(), 1e3));
    EXPECT_TRUE(factors.factorize(
      A.n, A.starts.data(), A.columns.data(), A.values.data(), 1e12));
  }

  /// Does EnvelopeCholesky<double> factorise @p A?
  bool
  factorizes(const Csr &A)
  {
    pdfem::Solvers::EnvelopeCholesky<double> factors;
    return factors.factorize(
      A.n, A.starts.data(), A.columns.data(), A.values.data(), 1e12);
  }

  /// @p A with @p value added to entry (row, column), inserted if absent.
  Csr
  with_entry(const Csr &A, const int row, const int column, const double value)
  {
    Csr B;
    B.n = A.n;
    for (std::size_t i = 0; i < A.n; ++i)
      {
        bool added = false;
        for (int k = A.starts[i]; k < A.starts[i + 1]; ++k)
          {
            const bool here = int(i) == row && A.columns[k] == column;
            B.columns.push_back(A.columns[k]);
            B.values.push_back(A.values[k] + (here ? value : 0.));
            added = added || here;
          }
        if (int(i) == row && !added)
          {
            B.columns.push_back(column);
            B.values.push_back(value);
          }
        B.starts.push_back(B.columns.size());
      }
    return B;
  }

  TEST(EnvelopeCholesky, RefusesUnsymmetricMatrices)
  {
    // Only the lower triangle is factorised: a matrix whose upper triangle
    // differs is refused, whichever triangle row 5's entries fall in after
    // the reordering. Rounding zeros in one row only are accepted.
    const Csr A = shuffled_grid_matrix(10, 1., 2);
    ASSERT_TRUE(factorizes(A));
    const int row = 5, neighbour = A.columns[A.starts[row]] == row ?
                                     A.columns[A.starts[row] + 1] :
                                     A.columns[A.starts[row]];
    EXPECT_FALSE(factorizes(with_entry(A, row, neighbour, 1e-3)));
    EXPECT_FALSE(factorizes(with_entry(A, neighbour, row, 1e-3)));
    // An entry in one row only, where the matrix has none (checked).
    bool coupled = false;
    for (int k = A.starts[0]; k < A.starts[1]; ++k)
      coupled = coupled || A.columns[k] == 99;
    ASSERT_FALSE(coupled);
    EXPECT_FALSE(factorizes(with_entry(A, 0, 99, 0.5)));
    EXPECT_FALSE(factorizes(with_entry(A, 99, 0, 0.5)));
    EXPECT_TRUE(factorizes(with_entry(A, 0, 99, 1e-20)));
    EXPECT_TRUE(factorizes(with_entry(A, 99, 0, 1e-20)));
    EXPECT_TRUE(factorizes(with_entry(A, row, neighbour, 1e-15)));
  }

  using namespace dealii;

  /// The grid matrix of shuffled_grid_matrix(80, shift) as a Trilinos
  /// matrix on one rank, deal.II's ML parameters for it (coarse solve
  /// Amesos-KLU) and the hierarchy they give.
  struct GridHierarchy
  {
    explicit GridHierarchy(const double shift)
    {
      const Csr              A   = shuffled_grid_matrix(80, shift, 9);
      const IndexSet         all = complete_index_set(A.n);
      DynamicSparsityPattern pattern(A.n);
      for (std::size_t i = 0; i < A.n; ++i)
        for (int k = A.starts[i]; k < A.starts[i + 1]; ++k)
          pattern.add(i, A.columns[k]);
      matrix.reinit(all, all, pattern, MPI_COMM_SELF);
      for (std::size_t i = 0; i < A.n; ++i)
        for (int k = A.starts[i]; k < A.starts[i + 1]; ++k)
          matrix.set(i, A.columns[k], A.values[k]);
      matrix.compress(VectorOperation::insert);

      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic = true;
      std::unique_ptr<Epetra_MultiVector> modes;
      data.set_parameters(list, modes, matrix);
      klu.initialize(matrix, list);
    }

    TrilinosWrappers::SparseMatrix    matrix;
    Teuchos::ParameterList            list;
    TrilinosWrappers::PreconditionAMG klu;
  };

  /// One V-cycle of @p amg applied to a random vector, twice: the results
  /// must be the same bit for bit.
  TrilinosWrappers::MPI::Vector
  v_cycle(const TrilinosWrappers::PreconditionAMG &amg, const std::size_t n)
  {
    TrilinosWrappers::MPI::Vector r(complete_index_set(n), MPI_COMM_SELF), z(r),
      again(r);
    std::mt19937                           gen(4);
    std::uniform_real_distribution<double> value(-1., 1.);
    for (const auto i : r.locally_owned_elements())
      r[i] = value(gen);
    r.compress(VectorOperation::insert);
    amg.vmult(z, r);
    amg.vmult(again, r);
    again -= z;
    EXPECT_EQ(again.linfty_norm(), 0.);
    return z;
  }

  TEST(EnvelopeCoarseSolve, SameVCycleAsKLUToSinglePrecision)
  {
    GridHierarchy                     grid(1e-2);
    TrilinosWrappers::PreconditionAMG envelope;
    ASSERT_TRUE(pdfem::Solvers::initialize_amg_with_envelope_coarse_solve(
      envelope, grid.matrix, grid.list));
    const TrilinosWrappers::MPI::Vector z_klu =
      v_cycle(grid.klu, grid.matrix.m());
    TrilinosWrappers::MPI::Vector z    = v_cycle(envelope, grid.matrix.m());
    const double                  size = z_klu.l2_norm();
    z -= z_klu;
    EXPECT_LT(z.l2_norm(), 1e-5 * size);
    EXPECT_GT(z.l2_norm(), 0.) << "float factors should round";
  }

  TEST(EnvelopeCoarseSolve, IndefiniteCoarseMatrixKeepsKLU)
  {
    // Shifted below its smallest eigenvalues, the matrix and its coarse
    // Galerkin matrix are indefinite: the hierarchy is built again as
    // deal.II's parameters ask, and its V-cycle is KLU's bit for bit.
    GridHierarchy                     grid(-0.05);
    TrilinosWrappers::PreconditionAMG fallback;
    EXPECT_FALSE(pdfem::Solvers::initialize_amg_with_envelope_coarse_solve(
      fallback, grid.matrix, grid.list));
    TrilinosWrappers::MPI::Vector z = v_cycle(fallback, grid.matrix.m());
    z -= v_cycle(grid.klu, grid.matrix.m());
    EXPECT_EQ(z.linfty_norm(), 0.);
  }
} // namespace
