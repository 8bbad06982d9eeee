// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/base/thread_team.h>
#include <pdfem/solvers/linear_solver.h>
#include <pdfem/solvers/ml_coarse_solve.h>
#include <pdfem/solvers/ml_threaded_products.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/tridiagonal_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>

namespace pdfem
{
  namespace Solvers
  {
    using namespace dealii;

    namespace
    {
      /// ML settings of both paths. Two Chebyshev (elliptic) sweeps: on the
      /// 3D box, 1 / 2 / 3 sweeps took 173 / 116 / 94 GMRES iterations, 2
      /// being the fastest.
      TrilinosWrappers::PreconditionAMG::AdditionalData
      amg_data(const bool                            elliptic,
               const std::vector<std::vector<bool>> &constant_modes)
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = elliptic;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        data.constant_modes        = constant_modes;
        return data;
      }

      /**
       * The matrix-free path's AMG: amg_data(), and in 2D the Chebyshev
       * sweeps after the coarse correction only (GMRES does not need a
       * symmetric preconditioner). On plateCrack FC1 that costs 8 % more
       * iterations (1 203 instead of 1 112) for a V-cycle 35 % cheaper;
       * FC2 1 816 instead of 1 758. In 3D the pre-sweeps matter: the box
       * needs 244 iterations without them instead of 39. ML's sparse
       * products then run on the process's threads (thread_ml_products):
       * V-cycle 1.34–1.55 ms instead of 1.75–1.89 on plateCrack FC1.
       */
      void
      initialize_amg(TrilinosWrappers::PreconditionAMG      &amg,
                     const TrilinosWrappers::SparseMatrix   &matrix,
                     const std::vector<std::vector<bool>>   &constant_modes,
                     const std::vector<std::vector<double>> &rotations,
                     const bool                              symmetric)
      {
        Teuchos::ParameterList              list;
        std::unique_ptr<Epetra_MultiVector> distributed_modes;
        amg_data(true, constant_modes)
          .set_parameters(list, distributed_modes, matrix);
        // 3D: the rotations beside the translations in the near null
        // space, and aggregates over every coupling (threshold 0). Measured
        // against translations and threshold 0.02, one rank: the paper's
        // 3D cantilever (bond based, 37 752 DoFs, CG) 300 -> 37 iterations,
        // 4.76 -> 1.47 s (rotations alone 202, threshold 0 alone 125); the
        // 3D box (boxVpd4_static, GMRES) 39 -> 28 iterations in the same
        // time, 854 -> 920 MB; the LPS dog-bone with 'amg fe' 236 -> 91
        // iterations, 54.9 -> 36.4 s, 2.5 -> 3.5 GB. In 2D the same
        // settings cost plateCrack FC1 888 -> 1 180 GMRES iterations, so
        // 2D keeps the translations and 0.02.
        std::unique_ptr<Epetra_MultiVector> modes;
        if (!rotations.empty() && distributed_modes)
          {
            list.set("aggregation: threshold", 0.);
            const int n_translations = distributed_modes->NumVectors();
            const int n_modes        = n_translations + int(rotations.size());
            modes =
              std::make_unique<Epetra_MultiVector>(distributed_modes->Map(),
                                                   n_modes);
            const int n_local = distributed_modes->MyLength();
            for (int m = 0; m < n_modes; ++m)
              for (int i = 0; i < n_local; ++i)
                (*modes)[m][i] = m < n_translations ?
                                   (*distributed_modes)[m][i] :
                                   rotations[m - n_translations][i];
            list.set("null space: type", "pre-computed");
            list.set("null space: dimension", n_modes);
            list.set("null space: vectors", modes->Values());
          }
        // One constant mode per displacement component: their number is
        // the dimension. CG needs the symmetric V-cycle.
        if (constant_modes.size() == 2 && !symmetric)
          list.set("smoother: pre or post", std::string("post"));
        initialize_amg_with_envelope_coarse_solve(amg, matrix, list);
        thread_ml_products(amg, ThreadTeam::shared());
      }
    } // namespace

    /**
     * Amesos (MUMPS or KLU) on one matrix: the symbolic analysis of its
     * pattern once, a numeric factorisation whenever its values changed,
     * any number of solves with it. deal.II's SolverDirect analyses and
     * factorises in one call. Measured on tests/scenes/rnp_cracked_plate_hard
     * (one rank, a new tangent at every Newton iteration, three alternating
     * pairs of runs): 12.4–13.1 s with the analysis kept, 13.9–14.3 s with
     * an analysis at every factorisation, the same history.csv.
     */
    struct LinearSolver::DirectFactorization
    {
      const TrilinosWrappers::SparseMatrix *matrix = nullptr;
      Epetra_LinearProblem                  problem;
      std::unique_ptr<Amesos_BaseSolver>    solver;
      /// The factors are those of the matrix's present values.
      bool factorized = false;
      /// Factors of earlier values of the same pattern exist.
      bool has_factors = false;
      /// How many solves with the factors cost one numeric factorisation
      /// in time (0 unknown, as with KLU): MUMPS's counts, its
      /// factorisation's flops over two per factor entry, divided by 10,
      /// since its dense kernels run the factorisation's flops about ten
      /// times faster than the triangular solves' (measured t_factorise /
      /// t_solve against that count: 14 / 140 on case 2 of Hu et al.,
      /// 38 / 358 and 63 / 735 on the 3D cantilever at 2 and 1 cm).
      double solves_per_factorization = 0.;
      /// Solves beyond one per solve spent with the present factors (the
      /// reuses' extra cost): reuse stops once it reaches the cost of a
      /// factorisation (ski rental: at most twice the best cost).
      double extra_solves = 0.;
      /// Changes of the matrix to factorise without trying the earlier
      /// factors, after reuses that did not converge (1, 3, 7, ... after
      /// 1, 2, 3 failures in a row).
      unsigned int skip_reuse = 0, failed_reuses = 0;

      /// x = the factors' solution for b.
      int
      solve(Epetra_MultiVector &x, const Epetra_MultiVector &b)
      {
        problem.SetLHS(&x);
        problem.SetRHS(const_cast<Epetra_MultiVector *>(&b));
        return solver->Solve();
      }
    };

    LinearSolver::LinearSolver(const Solvers::Settings &settings)
      : settings(settings)
    {}

    LinearSolver::~LinearSolver() = default;

    void
    LinearSolver::set_constant_modes(const std::vector<std::vector<bool>> &m)
    {
      constant_modes = m;
      amg.reset();
    }

    void
    LinearSolver::set_rotation_modes(
      const std::vector<std::vector<double>> &rotations)
    {
      rotation_modes = rotations;
      amg.reset();
    }

    unsigned int
    LinearSolver::solve(const TrilinosWrappers::SparseMatrix &K,
                        TrilinosWrappers::MPI::Vector        &x,
                        const TrilinosWrappers::MPI::Vector  &b,
                        const double                          allowed_residual)
    {
      unsigned int iterations = 1;
      if (!settings.iterative())
        {
          // One factorisation for every solve with the same matrix: an
          // arc-length step solves twice per iteration with one tangent
          // (rnp_cracked_plate_hard, one rank: 19.7 s with a factorisation
          // per solve, 13.9 s with it kept); one analysis while the pattern
          // stays (DirectFactorization).
          const auto fail = [this](const std::string &what, const int ierr) {
            matrix_rebuilt();
            throw RunFailure("singular matrix",
                             "the direct solver failed: " + what +
                               " returned " + std::to_string(ierr));
          };
          if (!direct || direct->matrix != &K)
            {
              matrix_rebuilt();
              direct         = std::make_unique<DirectFactorization>();
              direct->matrix = &K;
              direct->problem.SetOperator(
                const_cast<Epetra_CrsMatrix *>(&K.trilinos_matrix()));
              Amesos factory;
              direct->solver.reset(
                factory.Create(settings.direct_solver == "klu" ? "Amesos_Klu" :
                                                                 "Amesos_Mumps",
                               direct->problem));
              if (!direct->solver)
                fail("creating the Amesos solver", -1);
              if (const int ierr = direct->solver->SymbolicFactorization())
                fail("the symbolic analysis", ierr);
              ++analyses;
            }
          if (!direct->factorized && direct->has_factors &&
              settings.reuse_factorization)
            {
              const unsigned int its = solve_with_earlier_factors(K, x, b);
              if (its > 0)
                return its;
            }
          if (!direct->factorized)
            {
              if (const int ierr = direct->solver->NumericFactorization())
                fail("the numeric factorisation", ierr);
              direct->factorized  = true;
              direct->has_factors = true;
              ++factorizations;
              direct->solves_per_factorization = 0.;
              direct->extra_solves             = 0.;
              if (const auto *mumps =
                    dynamic_cast<Amesos_Mumps *>(direct->solver.get()))
                {
                  // RINFOG(3): the factorisation's flops; INFOG(29): the
                  // factors' entries (both summed over the ranks).
                  auto        *m       = const_cast<Amesos_Mumps *>(mumps);
                  const double flops   = m->GetRINFOG()[2];
                  const double entries = m->GetINFOG()[28];
                  if (flops > 0. && entries > 0.)
                    direct->solves_per_factorization =
                      0.1 * flops / (2. * entries);
                }
            }
          if (const int ierr =
                direct->solve(x.trilinos_vector(), b.trilinos_vector()))
            fail("the solve", ierr);
        }
      else if (settings.conjugate_gradients())
        iterations = solve_cg(K, x, b, allowed_residual);
      else
        {
          const double                  b_norm = b.l2_norm();
          SolverControl                 control(settings.max_iterations,
                                std::max(settings.tolerance * b_norm,
                                         allowed_residual),
                                false,
                                false);
          TrilinosWrappers::SolverGMRES solver(
            control,
            TrilinosWrappers::SolverGMRES::AdditionalData(false,
                                                          settings.restart));
          try
            {
              if (settings.preconditioner == "amg")
                {
                  // ML of the non-symmetric coupled matrix itself.
                  const bool rebuilt = prepare_matrix_amg(K, false);
                  SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
                    control,
                    SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                      settings.restart + 2, true));
                  x = 0.;
                  gmres.solve(K, x, b, *amg);
                  record_matrix_amg(rebuilt, control.last_step());
                }
              else
                {
                  TrilinosWrappers::PreconditionILU ilu;
                  ilu.initialize(
                    K,
                    TrilinosWrappers::PreconditionILU::AdditionalData(
                      1, 0., 1., 1));
                  solver.solve(K, x, b, ilu);
                }
            }
          catch (const std::exception &e)
            {
              throw RunFailure("linear solver diverged",
                               "GMRES did not reach the tolerance " +
                                 std::to_string(settings.tolerance) + " in " +
                                 std::to_string(control.last_step()) +
                                 " iterations");
            }
          iterations = control.last_step();
        }
      if (!std::isfinite(x.l2_norm()))
        throw RunFailure(!settings.iterative() ? "singular matrix" :
                                                 "linear solver diverged",
                         "the solution of the linear system is not finite");
      return iterations;
    }
    bool
    LinearSolver::prepare_matrix_amg(const TrilinosWrappers::SparseMatrix &K,
                                     const bool symmetric)
    {
      // Kept while the matrix only loses bonds (the same object), until
      // record_matrix_amg() found it stale.
      if (amg && amg_matrix == &K && !amg_stale)
        return false;
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      amg->initialize(K, amg_data(symmetric, constant_modes));
      amg_matrix = &K;
      amg_stale  = false;
      return true;
    }

    unsigned int
    LinearSolver::solve_with_earlier_factors(
      const TrilinosWrappers::SparseMatrix &K,
      TrilinosWrappers::MPI::Vector        &x,
      const TrilinosWrappers::MPI::Vector  &b)
    {
      // x_0 = the earlier factors' solution; then GMRES on K's new values
      // for the correction, preconditioned (on the right: the tolerance is
      // on the true residual) by the same factors, while the solves spent
      // beyond one per solve since the factorisation stay below what a
      // factorisation costs (at most 50 in one solve); where GMRES needs
      // more, 0 tells the caller to factorise, and the next changes skip
      // the attempt (1, 3, 7, ... after failures in a row). The budget
      // comes from MUMPS's operation counts, not from timings, so that a
      // run repeats itself to the bit. The target, 1e-12 of |b| (a direct
      // solve's accuracy for what the drivers check, whatever the
      // Tolerance of the iterative paths), does not go below what rounding
      // allows (10^-14 |K|_inf |x_0|): a right-hand side that is itself
      // round-off (a second Newton iteration of a linear problem) is done
      // with x_0.
      if (direct->skip_reuse > 0)
        {
          --direct->skip_reuse;
          return 0;
        }
      const double budget =
        std::min(direct->solves_per_factorization - direct->extra_solves, 50.);
      if (budget < 2.)
        return 0;
      const auto give_up = [this]() {
        ++direct->failed_reuses;
        direct->skip_reuse = (1u << std::min(direct->failed_reuses, 10u)) - 1;
        return 0u;
      };
      const auto apply_factors =
        [this](TrilinosWrappers::MPI::Vector       &z,
               const TrilinosWrappers::MPI::Vector &r) {
          if (const int ierr =
                direct->solve(z.trilinos_vector(), r.trilinos_vector()))
            throw RunFailure("singular matrix",
                             "the direct solver failed: the solve returned " +
                               std::to_string(ierr));
        };
      apply_factors(x, b);
      TrilinosWrappers::MPI::Vector r(b), dx(b);
      K.vmult(r, x);
      r.sadd(-1., 1., b);
      const double target =
        std::max(1e-12 * b.l2_norm(), 1e-14 * K.linfty_norm() * x.l2_norm());
      if (!std::isfinite(r.l2_norm()))
        return give_up();
      unsigned int iterations = 1;
      if (r.l2_norm() > target)
        {
          struct EarlierFactors
          {
            const decltype(apply_factors) &apply;
            void
            vmult(TrilinosWrappers::MPI::Vector       &z,
                  const TrilinosWrappers::MPI::Vector &v) const
            {
              apply(z, v);
            }
          };
          const unsigned int max_steps = static_cast<unsigned int>(budget) - 1;
          SolverControl      control(max_steps, target, false, false);
          SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
            control,
            SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
              max_steps + 2, true));
          dx = 0.;
          try
            {
              gmres.solve(K, dx, r, EarlierFactors{apply_factors});
            }
          catch (const SolverControl::NoConvergence &)
            {
              return give_up();
            }
          x += dx;
          iterations += control.last_step();
        }
      if (!std::isfinite(x.l2_norm()))
        return give_up();
      direct->failed_reuses = 0;
      direct->extra_solves += iterations - 1;
      ++reused_solves;
      reused_iterations += iterations;
      return iterations;
    }

    void
    LinearSolver::matrix_changed()
    {
      if (direct)
        direct->factorized = false;
    }

    void
    LinearSolver::matrix_rebuilt()
    {
      direct.reset();
    }

    void
    LinearSolver::forget_preconditioner()
    {
      matrix_rebuilt();
      amg.reset();
      amg_matrix           = nullptr;
      amg_stale            = false;
      amg_fresh_iterations = 0;
      last_iterations      = 0;
      fresh_auxiliary_amg  = false;
    }

    void
    LinearSolver::record_matrix_amg(const bool         rebuilt,
                                    const unsigned int iterations)
    {
      // Rebuilt once a solve needs twice the iterations it needed fresh.
      if (rebuilt)
        amg_fresh_iterations = std::max(iterations, 5u);
      else if (iterations > 2 * amg_fresh_iterations)
        amg_stale = true;
    }

    LinearSolver::RitzValues
    LinearSolver::last_ritz_values() const
    {
      // The signed eigenvalues of the Lanczos matrix (LAPACK's stev).
      RitzValues        ritz;
      const std::size_t n = lanczos_diagonal.size();
      if (n == 0 ||
          !std::all_of(lanczos_diagonal.begin(),
                       lanczos_diagonal.end(),
                       [](const double d) { return std::isfinite(d); }))
        return ritz;
      TridiagonalMatrix<double> T(n, true);
      for (std::size_t i = 0; i < n; ++i)
        {
          T(i, i) = lanczos_diagonal[i];
          if (i + 1 < n)
            T(i, i + 1) = lanczos_off_diagonal[i];
        }
      T.compute_eigenvalues(); // in ascending order (LAPACK's stev)
      ritz.known    = true;
      ritz.smallest = T.eigenvalue(0);
      ritz.largest  = T.eigenvalue(n - 1);
      for (std::size_t i = 0; i < n && T.eigenvalue(i) < 0.; ++i)
        ++ritz.n_negative;
      return ritz;
    }

    unsigned int
    LinearSolver::solve_cg(const TrilinosWrappers::SparseMatrix &K,
                           TrilinosWrappers::MPI::Vector        &x,
                           const TrilinosWrappers::MPI::Vector  &b,
                           const double allowed_residual)
    {
      // CG of the symmetric coupled matrix: ML AMG (symmetric smoothed
      // aggregation, kept as for GMRES) or ILU(1),
      // which is an incomplete Cholesky factorisation of a symmetric matrix.
      SolverControl                           control(settings.max_iterations,
                            std::max(settings.tolerance * b.l2_norm(),
                                     allowed_residual),
                            false,
                            false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      x = 0.;
      try
        {
          if (settings.preconditioner == "ilu")
            {
              TrilinosWrappers::PreconditionILU ilu;
              ilu.initialize(K,
                             TrilinosWrappers::PreconditionILU::AdditionalData(
                               1, 0., 1., 1));
              cg.solve(K, x, b, ilu);
            }
          else
            {
              const bool rebuilt = prepare_matrix_amg(K, true);
              cg.solve(K, x, b, *amg);
              record_matrix_amg(rebuilt, control.last_step());
            }
        }
      catch (const SolverControl::NoConvergence &e)
        {
          throw RunFailure("linear solver diverged",
                           "CG did not reach the tolerance " +
                             number(settings.tolerance) + " in " +
                             std::to_string(e.last_step) +
                             " iterations (residual reduced by " +
                             number(e.last_residual / b.l2_norm()) + ")");
        }
      catch (const std::exception &e)
        {
          throw RunFailure(
            "linear solver diverged",
            "CG: " +
              ParameterTools::clean_dealii_message(e.what()).substr(0, 200));
        }
      return control.last_step();
    }

    namespace
    {
      /// deal.II's solvers need an object with vmult().
      struct OperatorWrapper
      {
        const LinearSolver::Operator &op;
        void
        vmult(TrilinosWrappers::MPI::Vector       &y,
              const TrilinosWrappers::MPI::Vector &x) const
        {
          op(y, x);
        }
      };

      /**
       * AMG of the FE stiffness followed by one block-Jacobi correction with
       * the true operator: z = A(r), z += D^-1 (r - K z), D the node blocks
       * of K's diagonal. The FE stiffness is stiffer than the nonlocal PD
       * operator at high frequencies, so the AMG alone under-corrects them;
       * the correction uses the PD operator itself. On the 3D box: 109 -> 70
       * GMRES iterations for one extra product each (damping 0.7 no better,
       * 1.3 diverges; ML sweeps 1/2/3: 95/70/64 iterations, 2 fastest).
       */
      struct CorrectedAMG
      {
        const TrilinosWrappers::PreconditionAMG &amg;
        const LinearSolver::Operator            &K;
        const LinearSolver::Operator            &jacobi;
        mutable TrilinosWrappers::MPI::Vector    t, w;
        void
        vmult(TrilinosWrappers::MPI::Vector       &z,
              const TrilinosWrappers::MPI::Vector &r) const
        {
          amg.vmult(z, r);
          if (t.size() != r.size()) // once per solve: a reinit every
            {                       // iteration cost 4 % of plateCrack FC1
              t.reinit(r, true);
              w.reinit(r, true);
            }
          K(t, z);
          t.sadd(-1., 1., r);
          jacobi(w, t);
          z += w;
        }
      };
    } // namespace

    template <typename Preconditioner>
    unsigned int
    LinearSolver::krylov(const Operator                      &K,
                         TrilinosWrappers::MPI::Vector       &x,
                         const TrilinosWrappers::MPI::Vector &b,
                         const Preconditioner                &P,
                         const double                         allowed_residual)
    {
      const double  b_norm = b.l2_norm();
      SolverControl control(settings.max_iterations,
                            std::max(settings.tolerance * b_norm,
                                     allowed_residual),
                            false,
                            false);
      x = 0.;
      lanczos_diagonal.clear();
      lanczos_off_diagonal.clear();
      // Thrown out of CG's coefficient slot (stop_at_negative_curvature()).
      struct NegativeCurvature
      {};
      try
        {
          if (settings.conjugate_gradients())
            {
              SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
              double                                  beta_over_alpha = 0.;
              cg.connect_coefficients_slot(
                [this, &beta_over_alpha](const double alpha,
                                         const double beta) {
                  lanczos_diagonal.push_back(1. / alpha + beta_over_alpha);
                  lanczos_off_diagonal.push_back(std::sqrt(beta) / alpha);
                  beta_over_alpha = beta / alpha;
                  // alpha = r.z / p.Kp with r.z > 0: the same sign on
                  // every rank.
                  if (alpha < 0. && negative_curvature_stops)
                    throw NegativeCurvature();
                });
              cg.solve(OperatorWrapper{K}, x, b, P);
            }
          else
            SolverGMRES<TrilinosWrappers::MPI::Vector>(
              control,
              SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                settings.restart + 2, true))
              .solve(OperatorWrapper{K}, x, b, P);
        }
      catch (const NegativeCurvature &)
        {
          throw RunFailure("linear solver diverged",
                           "CG met negative curvature (p.Kp < 0) in "
                           "iteration " +
                             std::to_string(lanczos_diagonal.size()) +
                             ": the operator is indefinite");
        }
      catch (const SolverControl::NoConvergence &e)
        {
          throw RunFailure(
            "linear solver diverged",
            std::string(settings.conjugate_gradients() ? "CG" : "GMRES") +
              " did not reach the tolerance " + number(settings.tolerance) +
              " in " + std::to_string(e.last_step) +
              " iterations (residual reduced by " +
              number(e.last_residual / b_norm) + ")");
        }
      if (!std::isfinite(x.l2_norm()))
        throw RunFailure("linear solver diverged",
                         "the solution of the linear system is not finite");
      return control.last_step();
    }

    unsigned int
    LinearSolver::solve(const Operator                      &K,
                        TrilinosWrappers::MPI::Vector       &x,
                        const TrilinosWrappers::MPI::Vector &b,
                        const Operator                      &preconditioner,
                        const double                         allowed_residual)
    {
      last_iterations =
        krylov(K, x, b, OperatorWrapper{preconditioner}, allowed_residual);
      return last_iterations;
    }

    bool
    LinearSolver::has_preconditioner_for(
      const TrilinosWrappers::SparseMatrix &auxiliary) const
    {
      // The auxiliary matrix changes in place when cracks cut cells. ML's
      // finest level (smoother, residuals) reads the matrix itself, so
      // only the coarse levels go stale: they are rebuilt once GMRES needs
      // 10 % more iterations than right after the last build. On the
      // plateCrack FC1 input: 10 builds instead of 34, 1 109 iterations
      // instead of 1 069 (25 %: 7 builds, 1 152; 50 %: 4, 1 259).
      return amg && amg_matrix == &auxiliary &&
             !(amg_stale && 10 * last_iterations > 11 * amg_fresh_iterations);
    }

    void
    LinearSolver::prepare_preconditioner(
      const TrilinosWrappers::SparseMatrix &auxiliary)
    {
      // The auxiliary FE stiffness is symmetric positive definite.
      if (has_preconditioner_for(auxiliary))
        return;
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      initialize_amg(*amg,
                     auxiliary,
                     constant_modes,
                     rotation_modes,
                     settings.conjugate_gradients());
      amg_matrix          = &auxiliary;
      amg_stale           = false;
      fresh_auxiliary_amg = true;
    }

    unsigned int
    LinearSolver::solve(const Operator                       &K,
                        TrilinosWrappers::MPI::Vector        &x,
                        const TrilinosWrappers::MPI::Vector  &b,
                        const TrilinosWrappers::SparseMatrix &auxiliary,
                        const Operator                       &block_jacobi,
                        const double                          allowed_residual)
    {
      prepare_preconditioner(auxiliary);

      if (settings.conjugate_gradients())
        // The block-Jacobi correction after the AMG is not symmetric: CG
        // takes the symmetric V-cycle alone.
        last_iterations = krylov(K, x, b, *amg, allowed_residual);
      else if (block_jacobi)
        last_iterations = krylov(K,
                                 x,
                                 b,
                                 CorrectedAMG{*amg, K, block_jacobi, {}, {}},
                                 allowed_residual);
      else
        last_iterations = krylov(K, x, b, *amg, allowed_residual);
      // The iterations with an AMG built for this solve (or ahead of it)
      // are the measure of its going stale.
      if (fresh_auxiliary_amg)
        amg_fresh_iterations = last_iterations;
      fresh_auxiliary_amg = false;
      return last_iterations;
    }
  } // namespace Solvers
} // namespace pdfem
