// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SOLVERS_SOLVER_CHOICE_H
#define PDFEM_SOLVERS_SOLVER_CHOICE_H

#include <string>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    class JsonWriter;
  }

  namespace Solvers
  {
    /// The two ways a coupled system can solve K du = r.
    enum class SolvePath
    {
      /// GMRES with the coupled operator applied without assembling it,
      /// preconditioned by AMG of the FE stiffness ('amg fe').
      matrix_free,
      /// A sparse LU (MUMPS or KLU) of the assembled matrix, kept for every
      /// solve until the matrix changes.
      direct
    };

    /// "gmres (amg fe)" or "direct"; @p krylov names the matrix-free
    /// path's method ("gmres" or "cg").
    std::string
    to_string(SolvePath path, const std::string &krylov = "gmres");

    /**
     * `Linear solver/Type = auto` during a run: which path the next solve
     * takes, from what the solves so far cost (design.md, "Solver choice").
     *
     * The two paths differ in what they pay for:
     * - matrix-free GMRES pays at every solve (its iterations), nothing for a
     *   change of the matrix (broken bonds) beyond an occasional AMG rebuild,
     *   and needs no assembled matrix;
     * - a direct factorisation pays once per change of the matrix (a numeric
     *   factorisation, much more than a GMRES solve) and little per solve
     *   (two triangular solves), and needs the matrix and its factors in
     *   memory.
     * So the direct path wins when many solves share one matrix (load steps
     * without damage, several Newton iterations per tangent), GMRES when
     * nearly every solve follows new broken bonds (crack growth: on the
     * peer's quasi-static inputs 85-90 % of the solves).
     *
     * The rule, with phi the measured fraction of solves that followed a
     * change of the matrix:
     * - starting matrix-free, after at least 3 solves with phi <= 1/3 the
     *   direct path is tried once (if its factors fit in memory);
     * - once the direct path has done a factorisation and three solves
     *   without one, its expected cost per solve, t_solve + phi (t_factorise -
     *   t_solve), is compared with the mean GMRES solve: the direct path is
     *   left again (for good) when it is 25 % dearer;
     * - a GMRES solve that fails goes over to the direct path, if that fits,
     *   instead of ending the run.
     * A nonlinear model solved by matrix-free CG (@p may_switch false, @p
     * krylov "cg") keeps CG while its tangent is positive definite and goes
     * over to the direct path for good where a CG solve fails (negative
     * curvature among them) or a stability check finds the tangent
     * indefinite (leave_matrix_free()).
     * Every change of path and its reason is kept for summary.json and the
     * progress output. Times are the largest over the ranks, so that every
     * rank decides alike.
     */
    class SolverChoice
    {
    public:
      /**
       * @p start: the first path, for the reason @p why. @p may_switch:
       * the other path is possible at all (the matrix-free path needs a
       * linear PD model). @p direct_fits: whether the direct factors fit in
       * memory (and @p memory_note says why not, or the estimate). @p
       * krylov: the matrix-free path's method, "gmres" or "cg".
       */
      SolverChoice(SolvePath          start,
                   const std::string &why,
                   bool               may_switch,
                   bool               direct_fits,
                   const std::string &memory_note,
                   const std::string &krylov = "gmres");

      /// The name of @p path in this run ("cg (amg fe)", "direct").
      std::string
      name(SolvePath path) const
      {
        return to_string(path, krylov);
      }

      /// The path of the next solve.
      SolvePath
      path() const
      {
        return current;
      }

      /// The matrix (operator) changed since the last solve: bonds broke or
      /// held DoFs changed.
      void
      matrix_changed()
      {
        changed = true;
      }

      /// One solve on the current path took @p seconds (the largest over the
      /// ranks) with @p iterations; @p factorized: it included a direct
      /// numeric factorisation.
      void
      record(double seconds, unsigned int iterations, bool factorized);

      /// Before the next solve: change the path if the costs so far say
      /// so. Returns whether it changed (path() is the new one).
      bool
      reconsider();

      /// A matrix-free solve failed with @p message: go over to the direct
      /// path if it fits (returns true; the caller solves again), else
      /// false (the caller ends the run).
      bool
      matrix_free_failed(const std::string &message);

      /// The matrix-free path cannot go on for @p reason (a CG solve found
      /// the tangent indefinite): go over to the direct path for good if it
      /// fits (returns true), else false.
      bool
      leave_matrix_free(const std::string &reason);

      /// One change of path.
      struct Switch
      {
        /// The first solve on the new path (1 = the run's first).
        unsigned long solve;
        SolvePath     to;
        std::string   reason;
      };

      const std::vector<Switch> &
      switches() const
      {
        return changes;
      }

      /// The section "choice" of summary.json's "linear_solver".
      void
      write(IO::JsonWriter &json) const;

    private:
      void
      go(SolvePath to, const std::string &reason);

      SolvePath     start_path;
      SolvePath     current;
      std::string   start_reason;
      bool          may_switch;
      bool          direct_fits;
      std::string   memory_note;
      std::string   krylov;
      bool          changed            = true; // the first solve needs a matrix
      bool          tried_direct       = false;
      bool          settled            = false;
      unsigned long solves             = 0;
      unsigned long after_changes      = 0;
      unsigned long krylov_solves      = 0;
      double        krylov_seconds     = 0.;
      unsigned long krylov_iterations  = 0;
      unsigned long factorizing_solves = 0, plain_solves = 0;
      double        factorizing_seconds = 0., plain_seconds = 0.;
      /// The comparison that settled the choice, once made.
      std::string         verdict;
      std::vector<Switch> changes;
    };
  } // namespace Solvers
} // namespace pdfem

#endif
