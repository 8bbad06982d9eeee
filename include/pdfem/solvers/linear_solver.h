// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_LINEAR_SOLVER_H
#define PDFEM_SOLVERS_LINEAR_SOLVER_H

#include <pdfem/solvers/settings.h>

#include <functional>
#include <memory>
#include <vector>

namespace dealii
{
  namespace TrilinosWrappers
  {
    class SparseMatrix;
    class PreconditionAMG;
    namespace MPI
    {
      class Vector;
    }
  } // namespace TrilinosWrappers
} // namespace dealii

namespace pdfem
{
  namespace Solvers
  {
    /**
     * Solves K x = b for the coupled matrix: a direct sparse LU (Amesos
     * MUMPS or KLU), restarted GMRES preconditioned with Trilinos ML
     * algebraic multigrid or ILU, or, when the operator is symmetric
     * (Type = cg), conjugate gradients with a symmetric AMG or ILU. (MueLu is
     * not available in Debian's deal.II 9.4 build.) A failed or non-finite
     * solve throws RunFailure with exit state "singular matrix" (direct) or
     * "linear solver diverged" (iterative).
     */
    class LinearSolver
    {
    public:
      explicit LinearSolver(const Solvers::Settings &settings);
      ~LinearSolver();

      /**
       * Rigid-body-free constant modes for AMG (one mask per component over
       * the locally owned DoFs), set once per DoF layout.
       */
      void
      set_constant_modes(const std::vector<std::vector<bool>> &modes);

      /**
       * The infinitesimal rotations (one vector over the locally owned DoFs
       * each), added to the translations in the near null space of the
       * 'amg fe' AMG, whose aggregation threshold is then 0; empty:
       * translations only, threshold 0.02. CoupledSystem gives them in 3D
       * (measured in linear_solver.cc, initialize_amg()).
       */
      void
      set_rotation_modes(const std::vector<std::vector<double>> &rotations);

      /// Solve with the assembled @p K: direct, or GMRES or CG with ML AMG
      /// or ILU of K. Returns the number of iterations (1 for direct). GMRES
      /// stops at |b - K x| <= max(tolerance |b|, @p allowed_residual).
      /// The direct path keeps K's factorisation for the next solve with
      /// the same matrix object until matrix_changed() (and its symbolic
      /// analysis until matrix_rebuilt()); K must outlive the solver (or
      /// matrix_rebuilt() be called before K goes).
      unsigned int
      solve(const dealii::TrilinosWrappers::SparseMatrix &K,
            dealii::TrilinosWrappers::MPI::Vector        &x,
            const dealii::TrilinosWrappers::MPI::Vector  &b,
            double allowed_residual = 0.);

      /**
       * Solve with GMRES (right preconditioning, so the tolerance is on the
       * true residual) for an operator given only by its product @p K,
       * preconditioned by ML AMG built from @p auxiliary and, if
       * @p block_jacobi is given (w = D^-1 t with D the node blocks of K's
       * diagonal), one correction z += D^-1 (r - K z) after the AMG.
       * The AMG hierarchy is reused while @p auxiliary stays the same
       * matrix; after preconditioner_matrix_changed() it is rebuilt once
       * GMRES needs 10 % more iterations than right after the last build.
       * GMRES stops at |b - K x| <= max(tolerance |b|, @p allowed_residual).
       */
      using Operator =
        std::function<void(dealii::TrilinosWrappers::MPI::Vector &,
                           const dealii::TrilinosWrappers::MPI::Vector &)>;
      unsigned int
      solve(const Operator                               &K,
            dealii::TrilinosWrappers::MPI::Vector        &x,
            const dealii::TrilinosWrappers::MPI::Vector  &b,
            const dealii::TrilinosWrappers::SparseMatrix &auxiliary,
            const Operator                               &block_jacobi = {},
            double allowed_residual                                    = 0.);

      /**
       * Build now the AMG of @p auxiliary that the next solve() with it
       * would build (nothing if it has one that is not stale). Set-up calls
       * it before the PD model's per-bond arrays exist, so that ML's
       * transient memory (the sparse products of its hierarchy) and those
       * arrays are not held at once.
       */
      void
      prepare_preconditioner(
        const dealii::TrilinosWrappers::SparseMatrix &auxiliary);

      /// Would solve() with @p auxiliary use the AMG this solver has (built
      /// by prepare_preconditioner() or an earlier solve) instead of
      /// building one?
      bool
      has_preconditioner_for(
        const dealii::TrilinosWrappers::SparseMatrix &auxiliary) const;

      /**
       * Solve with CG or GMRES (Type) for an operator given by its product
       * @p K, preconditioned by the operator @p preconditioner (z = P r;
       * symmetric positive definite for CG), to |b - K x| <=
       * max(tolerance |b|, @p allowed_residual).
       */
      unsigned int
      solve(const Operator                              &K,
            dealii::TrilinosWrappers::MPI::Vector       &x,
            const dealii::TrilinosWrappers::MPI::Vector &b,
            const Operator                              &preconditioner,
            double                                       allowed_residual);

      /**
       * The assembled matrix given to solve() has new values in the same
       * sparsity pattern: the next direct solve factorises it again
       * (numerically; the symbolic analysis of the pattern is kept). Its
       * owner calls this whenever it writes the matrix (a kept
       * factorisation of the old values would give wrong solutions).
       */
      void
      matrix_changed();

      /**
       * The matrix given to solve() is rebuilt (a new sparsity pattern) or
       * goes: the direct path forgets its analysis and factorisation, which
       * refer to it. Its owner calls this before it reinitialises or frees
       * the matrix.
       */
      void
      matrix_rebuilt();

      /// Solve with a direct factorisation of the assembled matrix (@p
      /// direct) or with the Krylov method the solver had (GMRES if it had
      /// none): Type = auto changing its path.
      void
      use_direct(const bool direct)
      {
        if (settings.iterative())
          krylov_type = settings.type;
        settings.type = direct ? "direct" : krylov_type;
      }

      /**
       * CG stops at the first negative curvature p^T K p < 0 (a negative
       * step length alpha: the preconditioner is positive definite), with
       * RunFailure "linear solver diverged", instead of going on with an
       * operator proven indefinite. For Type = auto with a nonlinear model,
       * which then goes over to the direct path; plain `cg` goes on (CG may
       * still converge on an indefinite operator).
       */
      void
      stop_at_negative_curvature(const bool stop)
      {
        negative_curvature_stops = stop;
      }

      /// The number of direct numeric factorisations so far.
      unsigned int
      n_factorizations() const
      {
        return factorizations;
      }

      /// The number of solves with the factors of a matrix's earlier
      /// values (Factorization reuse), and their GMRES iterations.
      unsigned int
      n_reused_factorization_solves() const
      {
        return reused_solves;
      }
      unsigned int
      n_reused_factorization_iterations() const
      {
        return reused_iterations;
      }

      /// The number of direct symbolic analyses so far.
      unsigned int
      n_analyses() const
      {
        return analyses;
      }

      /**
       * The eigenvalue estimates (Ritz values) of the preconditioned
       * operator P^-1 K that the last CG solve's Lanczos coefficients give:
       * they lie inside P^-1 K's spectrum, and P^-1 K (P symmetric
       * positive definite) has the inertia of K, so a negative one proves
       * K indefinite. From the last solve of an operator (the solve()s
       * taking an Operator): `known` false where that was GMRES or took
       * fewer than two CG iterations. Computed when asked, from the
       * coefficients the solve kept.
       */
      struct RitzValues
      {
        bool         known      = false;
        double       smallest   = 0.;
        double       largest    = 0.;
        unsigned int n_negative = 0;
      };

      RitzValues
      last_ritz_values() const;

      /// The matrix the AMG was built from has new entries: the next solve
      /// rebuilds the hierarchy.
      void
      preconditioner_matrix_changed()
      {
        amg_stale = true;
      }

      /**
       * Forget the AMG hierarchy kept from earlier solves and its
       * iteration counts: the next solve builds one from the matrix as it
       * is then, as a run restarted from a checkpoint does. A checkpoint
       * calls it, so that the restarted run repeats the uninterrupted one
       * to the bit.
       */
      void
      forget_preconditioner();

    private:
      /// CG or GMRES (Type) from x = 0 with the preconditioner @p P (an
      /// object with vmult()); RunFailure where it does not converge.
      template <typename Preconditioner>
      unsigned int
      krylov(const Operator                              &K,
             dealii::TrilinosWrappers::MPI::Vector       &x,
             const dealii::TrilinosWrappers::MPI::Vector &b,
             const Preconditioner                        &P,
             double                                       allowed_residual);

      /// Build the ML hierarchy of the assembled @p K (symmetric smoothed
      /// aggregation for CG) unless the one kept is still good; returns
      /// whether it was built.
      bool
      prepare_matrix_amg(const dealii::TrilinosWrappers::SparseMatrix &K,
                         bool symmetric);

      /// After a solve with that hierarchy: mark it stale once a solve
      /// needs twice the iterations it needed when it was built.
      void
      record_matrix_amg(bool rebuilt, unsigned int iterations);

      /**
       * The direct path after matrix_changed() (Factorization reuse): the
       * factors of @p K's earlier values solve once, then GMRES on its new
       * values, preconditioned by them, corrects to the Tolerance, within
       * as many solves as MUMPS counts in one factorisation. Returns the
       * solves with the factors, or 0 where that budget does not suffice
       * (or is under 3, or unknown): then factorise.
       */
      unsigned int
      solve_with_earlier_factors(
        const dealii::TrilinosWrappers::SparseMatrix &K,
        dealii::TrilinosWrappers::MPI::Vector        &x,
        const dealii::TrilinosWrappers::MPI::Vector  &b);

      /// The assembled path with Type = cg.
      unsigned int
      solve_cg(const dealii::TrilinosWrappers::SparseMatrix &K,
               dealii::TrilinosWrappers::MPI::Vector        &x,
               const dealii::TrilinosWrappers::MPI::Vector  &b,
               double                                        allowed_residual);

      Solvers::Settings settings;
      /// The Krylov method use_direct(false) returns to.
      std::string                      krylov_type              = "gmres";
      bool                             negative_curvature_stops = false;
      std::vector<std::vector<bool>>   constant_modes;
      std::vector<std::vector<double>> rotation_modes;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
      const dealii::TrilinosWrappers::SparseMatrix *amg_matrix = nullptr;
      bool                                          amg_stale  = false;
      unsigned int                                  amg_fresh_iterations = 0;
      unsigned int                                  last_iterations      = 0;
      /// No solve has used the auxiliary AMG since it was built.
      bool fresh_auxiliary_amg = false;
      /// The last CG solve's Lanczos matrix (diagonal 1/alpha_i +
      /// beta_(i-1)/alpha_(i-1), off-diagonal sqrt(beta_i)/alpha_i, as
      /// deal.II's SolverCG builds it for its estimates, which it returns
      /// as absolute values) of the last solve of an operator; empty where
      /// that was GMRES.
      std::vector<double> lanczos_diagonal, lanczos_off_diagonal;
      /// The direct path's factorisation of *direct_matrix (nullptr: none
      /// kept), and the control SolverDirect refers to.
      /// The direct path's Amesos solver, its analysis of a matrix and,
      /// while that matrix is unchanged, its factorisation.
      struct DirectFactorization;
      std::unique_ptr<DirectFactorization> direct;
      unsigned int                         factorizations    = 0;
      unsigned int                         analyses          = 0;
      unsigned int                         reused_solves     = 0;
      unsigned int                         reused_iterations = 0;
    };
  } // namespace Solvers
} // namespace pdfem

#endif
