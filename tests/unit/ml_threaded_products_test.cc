// SPDX-License-Identifier: LGPL-2.1-or-later
// thread_ml_products: the ML V-cycle with its products shared among two
// threads gives the same result, bit for bit, as ML's own products, and the
// finest matrix, the restriction and the prolongation are all shared.
#include <pdfem/base/thread_team.h>
#include <pdfem/solvers/ml_threaded_products.h>

#include <deal.II/base/index_set.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <random>

#include <gtest/gtest.h>

namespace
{
  using namespace dealii;

  /// The 5-point Laplacian on an n x n grid with a shifted diagonal.
  void
  make_laplacian(const unsigned int n, TrilinosWrappers::SparseMatrix &A)
  {
    const auto id = [n](unsigned int i, unsigned int j) { return i * n + j; };
    DynamicSparsityPattern pattern(n * n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          pattern.add(id(i, j), id(i, j));
          if (i > 0)
            pattern.add(id(i, j), id(i - 1, j));
          if (i + 1 < n)
            pattern.add(id(i, j), id(i + 1, j));
          if (j > 0)
            pattern.add(id(i, j), id(i, j - 1));
          if (j + 1 < n)
            pattern.add(id(i, j), id(i, j + 1));
        }
    A.reinit(complete_index_set(n * n),
             complete_index_set(n * n),
             pattern,
             MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          A.set(id(i, j), id(i, j), 4.01);
          if (i > 0)
            A.set(id(i, j), id(i - 1, j), -1.);
          if (i + 1 < n)
            A.set(id(i, j), id(i + 1, j), -1.);
          if (j > 0)
            A.set(id(i, j), id(i, j - 1), -1.);
          if (j + 1 < n)
            A.set(id(i, j), id(i, j + 1), -1.);
        }
    A.compress(VectorOperation::insert);
  }

  TEST(MLThreadedProducts, SameVCycleBitForBit)
  {
    TrilinosWrappers::SparseMatrix A;
    make_laplacian(150, A); // 22 500 rows, 112 000 entries
    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    amg.initialize(A, data);

    TrilinosWrappers::MPI::Vector r(complete_index_set(A.m()), MPI_COMM_WORLD),
      serial(r), shared(r);
    std::mt19937                           gen(7);
    std::uniform_real_distribution<double> value(-1., 1.);
    for (const auto i : r.locally_owned_elements())
      r[i] = value(gen);
    r.compress(VectorOperation::insert);
    amg.vmult(serial, r);

    pdfem::ThreadTeam one(1), two(2);
    EXPECT_EQ(pdfem::Solvers::thread_ml_products(amg, one), 0u);
    // The finest matrix, the restriction and the prolongation.
    EXPECT_GE(pdfem::Solvers::thread_ml_products(amg, two), 3u);
    amg.vmult(shared, r);
    for (unsigned int round = 0; round < 3; ++round)
      {
        shared -= serial;
        EXPECT_EQ(shared.linfty_norm(), 0.);
        amg.vmult(shared, r);
      }
    EXPECT_GT(serial.l2_norm(), 0.);
  }
} // namespace
