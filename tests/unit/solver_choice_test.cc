// SPDX-License-Identifier: LGPL-2.1-or-later
// Solvers::SolverChoice (Linear solver Type = auto): the direct path is tried
// where solves reuse one matrix, kept or left by its measured cost, taken
// when GMRES fails, and never where its factors do not fit.
#include <pdfem/base/json_writer.h>
#include <pdfem/solvers/solver_choice.h>

#include <sstream>

#include <gtest/gtest.h>

namespace
{
  using pdfem::Solvers::SolvePath;
  using pdfem::Solvers::SolverChoice;

  SolverChoice
  matrix_free_start(const bool fits = true)
  {
    return SolverChoice(SolvePath::matrix_free, "test", true, fits, "note");
  }

  /// @p n solves on the current path, each after a change of the matrix
  /// if @p changed; direct solves factorise when the matrix changed.
  void
  solves(SolverChoice      &choice,
         const unsigned int n,
         const bool         changed,
         const double       seconds,
         const unsigned int iterations = 20)
  {
    for (unsigned int i = 0; i < n; ++i)
      {
        if (changed)
          choice.matrix_changed();
        ASSERT_FALSE(choice.reconsider());
        choice.record(seconds, iterations, false);
      }
  }

  TEST(SolverChoice, GrowthKeepsGMRES)
  {
    // Every solve after broken bonds (crack growth): never a factorisation.
    SolverChoice choice = matrix_free_start();
    solves(choice, 50, true, 0.05);
    EXPECT_EQ(choice.path(), SolvePath::matrix_free);
    EXPECT_TRUE(choice.switches().empty());
  }

  TEST(SolverChoice, ReusedMatrixTriesDirectAndKeepsItWhenCheaper)
  {
    SolverChoice choice = matrix_free_start();
    // The first solve needs a matrix; two more reuse it.
    choice.record(0.05, 40, false);
    choice.record(0.05, 40, false);
    choice.record(0.05, 40, false);
    ASSERT_TRUE(choice.reconsider());
    EXPECT_EQ(choice.path(), SolvePath::direct);
    ASSERT_EQ(choice.switches().size(), 1u);
    EXPECT_EQ(choice.switches()[0].solve, 4u);
    // The direct path's first solve factorises, later ones do not.
    choice.record(0.2, 1, true);
    for (unsigned int i = 0; i < 3; ++i)
      {
        EXPECT_FALSE(choice.reconsider());
        choice.record(0.002, 1, false);
      }
    // Both direct costs are known: 1 change in 7 solves, 0.002 + 0.198 / 7
    // = 0.030 s per solve against 0.05: kept, and settled.
    EXPECT_FALSE(choice.reconsider());
    EXPECT_EQ(choice.path(), SolvePath::direct);
    solves(choice, 20, false, 0.002);
    EXPECT_EQ(choice.switches().size(), 1u);
  }

  TEST(SolverChoice, DearerDirectGoesBackForGood)
  {
    SolverChoice choice = matrix_free_start();
    solves(choice, 3, false, 0.01);
    ASSERT_TRUE(choice.reconsider());
    choice.record(2.0, 1, true); // an expensive factorisation
    for (unsigned int i = 0; i < 3; ++i)
      {
        ASSERT_FALSE(choice.reconsider());
        choice.record(0.5, 1, false);
      }
    ASSERT_TRUE(choice.reconsider());
    EXPECT_EQ(choice.path(), SolvePath::matrix_free);
    ASSERT_EQ(choice.switches().size(), 2u);
    EXPECT_NE(choice.switches()[1].reason.find("against 0.01 s with GMRES"),
              std::string::npos)
      << choice.switches()[1].reason;
    // Never tried again, however many solves reuse the matrix.
    solves(choice, 30, false, 0.01);
    EXPECT_EQ(choice.path(), SolvePath::matrix_free);
  }

  TEST(SolverChoice, FrequentChangesOrTooFewSolvesDoNotTry)
  {
    // Half the solves after a change: phi = 1/2 > 1/3.
    SolverChoice choice = matrix_free_start();
    for (unsigned int i = 0; i < 20; ++i)
      {
        if (i % 2 == 0)
          choice.matrix_changed();
        ASSERT_FALSE(choice.reconsider());
        choice.record(0.05, 20, false);
      }
    // Two solves are not enough to judge.
    SolverChoice early = matrix_free_start();
    early.record(0.05, 20, false);
    early.record(0.05, 20, false);
    EXPECT_FALSE(early.reconsider());
  }

  TEST(SolverChoice, FactorsThatDoNotFitAreNeverTried)
  {
    SolverChoice choice = matrix_free_start(false);
    solves(choice, 20, false, 0.05);
    EXPECT_EQ(choice.path(), SolvePath::matrix_free);
    EXPECT_FALSE(choice.matrix_free_failed("GMRES did not converge"));
  }

  TEST(SolverChoice, FailedGMRESGoesDirectForGood)
  {
    SolverChoice choice = matrix_free_start();
    choice.record(0.05, 20, false);
    ASSERT_TRUE(choice.matrix_free_failed("GMRES did not converge"));
    EXPECT_EQ(choice.path(), SolvePath::direct);
    EXPECT_EQ(choice.switches().back().reason,
              "GMRES failed: GMRES did not converge");
    choice.record(0.3, 1, true);
    solves(choice, 5, false, 0.001);
    EXPECT_EQ(choice.path(), SolvePath::direct);
  }

  TEST(SolverChoice, NonlinearCGNeverSwitchesByCostAndLeavesForGood)
  {
    // A nonlinear model on matrix-free CG: no choice by cost (every solve
    // follows a new tangent), the direct path once CG finds the tangent
    // indefinite, and no way back.
    SolverChoice choice(
      SolvePath::matrix_free, "nonlinear", false, true, "", "cg");
    EXPECT_EQ(choice.name(SolvePath::matrix_free), "cg (amg fe)");
    solves(choice, 10, false, 0.05, 60);
    EXPECT_EQ(choice.path(), SolvePath::matrix_free);
    ASSERT_TRUE(choice.matrix_free_failed("CG met negative curvature"));
    EXPECT_EQ(choice.path(), SolvePath::direct);
    EXPECT_EQ(choice.switches().back().reason,
              "CG failed: CG met negative curvature");
    EXPECT_EQ(choice.switches().back().solve, 11u);
    EXPECT_FALSE(choice.leave_matrix_free("again"));
    choice.record(0.3, 1, true);
    solves(choice, 5, true, 0.001);
    EXPECT_EQ(choice.path(), SolvePath::direct);
    EXPECT_EQ(choice.switches().size(), 1u);
    std::ostringstream out;
    {
      pdfem::IO::JsonWriter json(out);
      json.begin_object();
      choice.write(json);
      json.end_object();
    }
    for (const char *part : {"\"start\": \"cg (amg fe)\"",
                             "\"cg_solves\": 10",
                             "\"cg_iterations_per_solve\": 60",
                             "\"to\": \"direct\""})
      EXPECT_NE(out.str().find(part), std::string::npos) << part;
  }

  TEST(SolverChoice, MatrixFreeIsLeftOnlyWhereDirectFits)
  {
    SolverChoice choice(
      SolvePath::matrix_free, "nonlinear", false, false, "too much", "cg");
    EXPECT_FALSE(choice.leave_matrix_free("CG found the tangent indefinite"));
    EXPECT_EQ(choice.path(), SolvePath::matrix_free);
    EXPECT_TRUE(choice.switches().empty());
  }

  TEST(SolverChoice, ADirectStartWithoutAlternativeStays)
  {
    SolverChoice choice(SolvePath::direct, "nonlinear", false, true, "");
    solves(choice, 10, false, 0.01);
    EXPECT_EQ(choice.path(), SolvePath::direct);
    EXPECT_FALSE(choice.matrix_free_failed("x"));
  }

  TEST(SolverChoice, SummaryNamesStartReasonAndSwitches)
  {
    SolverChoice choice = matrix_free_start();
    solves(choice, 3, false, 0.05, 30);
    ASSERT_TRUE(choice.reconsider());
    std::ostringstream out;
    {
      pdfem::IO::JsonWriter json(out);
      json.begin_object();
      choice.write(json);
      json.end_object();
    }
    const std::string text = out.str();
    for (const char *part : {"\"start\": \"gmres (amg fe)\"",
                             "\"reason\": \"test\"",
                             "\"gmres_iterations_per_solve\": 30",
                             "\"to\": \"direct\"",
                             "2 of 3 solves reused an unchanged matrix"})
      EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
  }
} // namespace
