// SPDX-License-Identifier: LGPL-2.1-or-later
// LinearSolver's direct path keeps a matrix's factorisation for later solves
// with the same matrix, factorises again (numerically, the analysis kept)
// after matrix_changed() and analyses again after matrix_rebuilt(): solves
// after a change must use the new entries (a kept factorisation of the old
// ones would give the old solution). CG reports the signed Ritz values of
// its Lanczos matrix (the matrix-free stability check reads them).
#include <pdfem/base/exceptions.h>
#include <pdfem/solvers/linear_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>

#include <gtest/gtest.h>

namespace
{
  using namespace dealii;

  /// The n x n tridiagonal matrix (-1, d, -1) on this rank's rows.
  void
  make_tridiagonal(TrilinosWrappers::SparseMatrix &A,
                   const IndexSet                 &owned,
                   const double                    d)
  {
    const unsigned int                n = owned.size();
    TrilinosWrappers::SparsityPattern sp(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      for (unsigned int j = (i > 0 ? i - 1 : 0);
           j <= std::min(n - 1u, unsigned(i) + 1);
           ++j)
        sp.add(i, j);
    sp.compress();
    A.reinit(sp);
    for (const auto i : owned)
      for (unsigned int j = (i > 0 ? i - 1 : 0);
           j <= std::min(n - 1u, unsigned(i) + 1);
           ++j)
        A.set(i, j, i == j ? d : -1.);
    A.compress(VectorOperation::insert);
  }

  /// Rows 0 .. n-1 in contiguous blocks, one per rank.
  IndexSet
  owned_rows(const unsigned int n)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    IndexSet owned(n);
    owned.add_range(n * rank / n_ranks, n * (rank + 1) / n_ranks);
    owned.compress();
    return owned;
  }

  /// The direct solver with Amesos package @p package (mumps or klu).
  pdfem::Solvers::Settings
  direct_settings(const std::string &package)
  {
    pdfem::Solvers::Settings settings;
    settings.type          = "direct";
    settings.direct_solver = package;
    return settings;
  }

  /// |A x - b| / |b|.
  double
  relative_residual(const TrilinosWrappers::SparseMatrix &A,
                    const TrilinosWrappers::MPI::Vector  &x,
                    const TrilinosWrappers::MPI::Vector  &b)
  {
    TrilinosWrappers::MPI::Vector r(b);
    A.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }

  TEST(LinearSolver, DirectKeepsTheFactorisationUntilTheMatrixChanges)
  {
    for (const std::string package : {"mumps", "klu"})
      {
        const IndexSet owned = owned_rows(40);

        // The matrices outlive the solver: its factorisation refers to them.
        TrilinosWrappers::SparseMatrix A, B;
        pdfem::Solvers::LinearSolver   solver(direct_settings(package));

        make_tridiagonal(A, owned, 3.);
        TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b), y(b);
        for (const auto i : owned)
          b[i] = 1. + 0.1 * i;
        b.compress(VectorOperation::insert);

        solver.solve(A, x, b);
        EXPECT_LT(relative_residual(A, x, b), 1e-13) << package;
        // A second right-hand side with the same matrix: no new
        // factorisation.
        TrilinosWrappers::MPI::Vector b2(b);
        b2 *= -2.;
        solver.solve(A, y, b2);
        EXPECT_LT(relative_residual(A, y, b2), 1e-13) << package;
        EXPECT_EQ(solver.n_factorizations(), 1u) << package;

        // New values in the same pattern: after matrix_changed() the
        // solve uses them, with a new numeric factorisation and the same
        // analysis.
        for (const auto i : owned)
          A.set(i, i, 5.);
        A.compress(VectorOperation::insert);
        solver.matrix_changed();
        solver.solve(A, x, b);
        EXPECT_LT(relative_residual(A, x, b), 1e-13) << package;
        EXPECT_EQ(solver.n_factorizations(), 2u) << package;
        EXPECT_EQ(solver.n_analyses(), 1u) << package;

        // The matrix rebuilt (matrix_rebuilt() before, since the
        // factorisation refers to it): analysed and factorised again.
        solver.matrix_rebuilt();
        make_tridiagonal(A, owned, 6.);
        solver.solve(A, x, b);
        EXPECT_LT(relative_residual(A, x, b), 1e-13) << package;
        EXPECT_EQ(solver.n_factorizations(), 3u) << package;
        EXPECT_EQ(solver.n_analyses(), 2u) << package;

        // Another matrix object is analysed, whatever the caller says.
        make_tridiagonal(B, owned, 4.);
        solver.solve(B, x, b);
        EXPECT_LT(relative_residual(B, x, b), 1e-13) << package;
        EXPECT_EQ(solver.n_factorizations(), 4u) << package;
        EXPECT_EQ(solver.n_analyses(), 3u) << package;
      }
  }
  /// The 7-point Laplacian of an n x n x n grid with diagonal @p d (rows
  /// in blocks over the ranks): its factors cost many solves, as a 3D PD
  /// tangent's do.
  void
  make_laplacian(TrilinosWrappers::SparseMatrix &A,
                 const IndexSet                 &owned,
                 const unsigned int              n,
                 const double                    d)
  {
    const auto neighbours = [n](const unsigned int i) {
      std::vector<unsigned int> list{i};
      unsigned int              stride = 1;
      for (unsigned int axis = 0; axis < 3; ++axis, stride *= n)
        {
          const unsigned int c = (i / stride) % n;
          if (c > 0)
            list.push_back(i - stride);
          if (c + 1 < n)
            list.push_back(i + stride);
        }
      return list;
    };
    TrilinosWrappers::SparsityPattern sp(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      for (const unsigned int j : neighbours(i))
        sp.add(i, j);
    sp.compress();
    A.reinit(sp);
    for (const auto i : owned)
      for (const unsigned int j : neighbours(i))
        A.set(i, j, i == j ? d : -1.);
    A.compress(VectorOperation::insert);
  }

  TEST(LinearSolver, ChangedMatrixIsSolvedWithTheEarlierFactorsWhileThatPays)
  {
    const unsigned int             n     = 24;
    const IndexSet                 owned = owned_rows(n * n * n);
    TrilinosWrappers::SparseMatrix A;
    make_laplacian(A, owned, n, 6.1);
    TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b);
    for (const auto i : owned)
      b[i] = 1. + std::sin(0.1 * i);
    b.compress(VectorOperation::insert);

    for (const bool reuse : {true, false})
      {
        pdfem::Solvers::Settings settings = direct_settings("mumps");
        settings.reuse_factorization      = reuse;
        pdfem::Solvers::LinearSolver solver(settings);
        make_laplacian(A, owned, n, 6.1);
        solver.solve(A, x, b);
        EXPECT_EQ(solver.n_factorizations(), 1u);

        // A new tangent a little different (as Newton's next one): GMRES
        // with the earlier factors reaches the tolerance in a few
        // iterations, and the solution is that of the new values.
        for (const auto i : owned)
          A.set(i, i, 6.1 * (1. + 0.005 * std::cos(0.3 * i)));
        A.compress(VectorOperation::insert);
        solver.matrix_changed();
        const unsigned int its = solver.solve(A, x, b);
        EXPECT_LT(relative_residual(A, x, b), 1e-9) << reuse;
        if (reuse)
          {
            EXPECT_EQ(solver.n_factorizations(), 1u);
            EXPECT_EQ(solver.n_reused_factorization_solves(), 1u);
            EXPECT_GT(its, 1u);
            EXPECT_LT(its, 10u);
            EXPECT_EQ(solver.n_reused_factorization_iterations(), its);
          }
        else
          {
            EXPECT_EQ(solver.n_factorizations(), 2u);
            EXPECT_EQ(solver.n_reused_factorization_solves(), 0u);
          }

        // Values far from the factors' (an indefinite shift): GMRES does
        // not converge within the budget, the matrix is factorised again.
        for (const auto i : owned)
          A.set(i, i, i % 7 == 0 ? -3. : 6.1);
        A.compress(VectorOperation::insert);
        solver.matrix_changed();
        solver.solve(A, x, b);
        EXPECT_LT(relative_residual(A, x, b), 1e-9) << reuse;
        EXPECT_EQ(solver.n_factorizations(), reuse ? 2u : 3u);
        EXPECT_EQ(solver.n_reused_factorization_solves(), reuse ? 1u : 0u);
        if (!reuse)
          continue;

        // After that failure the next change is factorised without trying
        // the factors; the one after it tries them again.
        for (const unsigned int change : {1u, 2u})
          {
            for (const auto i : owned)
              A.set(i,
                    i,
                    (i % 7 == 0 ? -3. : 6.1) *
                      (1. + 0.001 * change * std::sin(0.2 * i)));
            A.compress(VectorOperation::insert);
            solver.matrix_changed();
            solver.solve(A, x, b);
            EXPECT_LT(relative_residual(A, x, b), 1e-9) << change;
          }
        EXPECT_EQ(solver.n_factorizations(), 3u);
        EXPECT_EQ(solver.n_reused_factorization_solves(), 2u);
      }
  }

  /// The product with @p A, as the operator interface of solve() takes it.
  pdfem::Solvers::LinearSolver::Operator
  product_of(const TrilinosWrappers::SparseMatrix &A)
  {
    return [&A](TrilinosWrappers::MPI::Vector       &y,
                const TrilinosWrappers::MPI::Vector &v) { A.vmult(y, v); };
  }

  /// CG (tolerance 1e-12, no preconditioner) on (-1, @p d, -1) with
  /// b_i = 1 + 0.1 i through the operator interface; the failure's message,
  /// or empty where CG converged.
  std::string
  solve_tridiagonal_with_cg(pdfem::Solvers::LinearSolver &solver,
                            const IndexSet               &owned,
                            const double                  d)
  {
    TrilinosWrappers::SparseMatrix A;
    make_tridiagonal(A, owned, d);
    TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b);
    for (const auto i : owned)
      b[i] = 1. + 0.1 * i;
    b.compress(VectorOperation::insert);
    const auto                                   product = product_of(A);
    const pdfem::Solvers::LinearSolver::Operator identity =
      [](TrilinosWrappers::MPI::Vector       &z,
         const TrilinosWrappers::MPI::Vector &r) { z = r; };
    try
      {
        solver.solve(product, x, b, identity, 0.);
      }
    catch (const pdfem::RunFailure &e)
      {
        EXPECT_EQ(e.exit_state, "linear solver diverged");
        return e.what();
      }
    return "";
  }

  pdfem::Solvers::Settings
  cg_settings()
  {
    pdfem::Solvers::Settings settings;
    settings.type      = "cg";
    settings.tolerance = 1e-12;
    return settings;
  }

  TEST(LinearSolver, ConjugateGradientsReportSignedRitzValues)
  {
    // (-1, d, -1) of size n has the eigenvalues d - 2 cos(k pi / (n + 1)),
    // k = 1 .. n: positive definite for d = 2.5, indefinite (two negative)
    // for d = 1.95. CG's Ritz values lie inside the spectrum, signed.
    const unsigned int n      = 40;
    const IndexSet     owned  = owned_rows(n);
    const double       lowest = -2. * std::cos(M_PI / (n + 1)),
                 highest      = 2. * std::cos(M_PI / (n + 1));
    for (const double d : {2.5, 1.95})
      {
        pdfem::Solvers::LinearSolver solver(cg_settings());
        EXPECT_FALSE(solver.last_ritz_values().known);
        // CG may fail on the indefinite matrix; its Ritz values stay.
        solve_tridiagonal_with_cg(solver, owned, d);
        const auto ritz = solver.last_ritz_values();
        ASSERT_TRUE(ritz.known) << d;
        EXPECT_GE(ritz.smallest, d + lowest - 1e-9) << d;
        EXPECT_LE(ritz.largest, d + highest + 1e-9) << d;
        if (d > 2.)
          {
            EXPECT_EQ(ritz.n_negative, 0u);
            EXPECT_NEAR(ritz.smallest, d + lowest, 1e-6);
          }
        else
          EXPECT_GE(ritz.n_negative, 1u);
      }
  }

  TEST(LinearSolver, ConjugateGradientsStopAtNegativeCurvatureWhenAsked)
  {
    // (-1, d, -1): for d = 1 the smooth right-hand side lies mostly on
    // eigenvalues near d - 2 < 0, so CG meets p.Kp < 0 at once; for d = 2.5
    // (positive definite) it never does. Only with the flag does CG stop
    // there (Type = auto with a nonlinear model, which then factorises).
    const IndexSet owned = owned_rows(40);
    for (const double d : {1., 2.5})
      for (const bool stop : {false, true})
        {
          pdfem::Solvers::LinearSolver solver(cg_settings());
          solver.stop_at_negative_curvature(stop);
          const std::string failure =
            solve_tridiagonal_with_cg(solver, owned, d);
          const bool negative_curvature =
            failure.find("negative curvature (p.Kp < 0) in iteration 1") !=
            std::string::npos;
          EXPECT_EQ(negative_curvature, stop && d < 2.) << d << " " << failure;
          if (d > 2.)
            {
              EXPECT_TRUE(failure.empty()) << failure;
            }
        }
  }

  TEST(LinearSolver, DirectOnASingularMatrixFailsWithOneLine)
  {
    for (const std::string package : {"mumps", "klu"})
      {
        const IndexSet                 owned = owned_rows(10);
        TrilinosWrappers::SparseMatrix A;
        // A zero first row and column: exactly singular.
        make_tridiagonal(A, owned, 2.);
        for (const auto i : owned)
          if (i == 0)
            {
              A.set(0, 0, 0.);
              A.set(0, 1, 0.);
            }
          else if (i == 1)
            A.set(1, 0, 0.);
        A.compress(VectorOperation::insert);
        pdfem::Solvers::LinearSolver  solver(direct_settings(package));
        TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b);
        for (const auto i : owned)
          b[i] = 1.;
        b.compress(VectorOperation::insert);
        try
          {
            solver.solve(A, x, b);
            ADD_FAILURE() << package << ": a singular matrix was solved";
          }
        catch (const pdfem::RunFailure &e)
          {
            EXPECT_EQ(e.exit_state, "singular matrix") << package;
            const std::string what = e.what();
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
            EXPECT_NE(what.find("the direct solver failed"), std::string::npos)
              << what;
          }
      }
  }

  TEST(LinearSolver, PreparedPreconditionerIsTheOneTheSolveUses)
  {
    // GMRES with "amg fe" on (-1, 2.5, -1) as an operator, its matrix the
    // auxiliary one: the AMG built by prepare_preconditioner() before the
    // first solve gives the solve that builds its own, the same bit for
    // bit, and is not built again (the set-up order of a run that solves).
    const IndexSet                 owned = owned_rows(200);
    TrilinosWrappers::SparseMatrix A;
    make_tridiagonal(A, owned, 2.5);
    TrilinosWrappers::MPI::Vector b(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      b[i] = std::sin(0.1 * i);
    b.compress(VectorOperation::insert);
    const auto               product = product_of(A);
    pdfem::Solvers::Settings settings;
    settings.type           = "gmres";
    settings.preconditioner = "amg fe";
    settings.tolerance      = 1e-12;

    std::vector<TrilinosWrappers::MPI::Vector> x(2, b);
    std::vector<unsigned int>                  iterations(2);
    for (const bool prepared : {false, true})
      {
        pdfem::Solvers::LinearSolver solver(settings);
        solver.set_constant_modes(
          {std::vector<bool>(owned.n_elements(), true)});
        EXPECT_FALSE(solver.has_preconditioner_for(A));
        if (prepared)
          {
            solver.prepare_preconditioner(A);
            EXPECT_TRUE(solver.has_preconditioner_for(A));
          }
        iterations[prepared] = solver.solve(product, x[prepared], b, A);
        EXPECT_TRUE(solver.has_preconditioner_for(A));
        EXPECT_LT(relative_residual(A, x[prepared], b), 1e-11);
      }
    EXPECT_EQ(iterations[0], iterations[1]);
    EXPECT_GT(iterations[0], 0u);
    x[1] -= x[0];
    EXPECT_EQ(x[1].linfty_norm(), 0.);
  }
} // namespace
