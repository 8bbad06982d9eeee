// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_NEWTON_DRIVER_H
#define PDFEM_DRIVERS_NEWTON_DRIVER_H

#include <pdfem/drivers/progress_pulse.h>
#include <pdfem/drivers/resume.h>
#include <pdfem/drivers/settings.h>
#include <pdfem/drivers/static_driver.h>
#include <pdfem/drivers/system_interface.h>

#include <cstddef>
#include <functional>

namespace pdfem
{
  namespace Drivers
  {
    /** The stability of a converged state (specs/001 §2.5). */
    struct StabilityReport
    {
      /// The reduced tangent is numerically singular (a zero pivot).
      bool singular = false;
      /// Its number of negative eigenvalues (0: positive definite, stable).
      std::size_t n_negative = 0;
      /// Smallest |pivot| / max |K_ii| of its factorisation.
      double smallest_relative_pivot = 0.;

      bool
      stable() const
      {
        return !singular && n_negative == 0;
      }
    };

    /**
     * A system whose tangent can be tested for definiteness: the tangent
     * last assembled by residual(), reduced to the free DoFs and made
     * symmetric (rows scaled by the nodal volumes), is it positive definite?
     */
    class StabilityInterface
    {
    public:
      virtual ~StabilityInterface() = default;

      virtual StabilityReport
      check_stability() = 0;
    };

    /** Why a Newton run stopped early, and where. */
    struct NewtonOutcome
    {
      /// The last load factor with a converged, stable state (0: none).
      double last_stable_load = 0.;
      /// The load factor that could not be reached (unstable runs).
      double failure_load = 0.;
      /// Load step cuts made in the whole run.
      unsigned int n_cuts = 0;
      /// The last stability check of a converged state.
      StabilityReport last_check;
      /// Converged states rejected because they were not stable.
      unsigned int n_unstable_states = 0;
      /// Load control: folds passed by following the path (snap-backs).
      unsigned int n_snap_backs = 0;
      /// Load control: states on those paths (stable or not).
      unsigned int n_path_states = 0;
    };

    /**
     * Newton's method with load stepping for soft (forces, tractions, body
     * force) and hard (prescribed displacement) loading (specs/000 §3,
     * specs/001 §2.3-2.5), in pdfem's convention K du = r, r = f_ext -
     * f_int.
     *
     * - The load factor goes from 0 to 1 in `Load steps` increments; each
     *   step starts from the secant extrapolation of the last two converged
     *   states with the prescribed DoFs at their new values.
     * - Each iteration is damped by a backtracking line search on |r|
     *   (accept u + a du once |r| <= (1 - 1e-4 a) |r_k|; a = 1, 1/2, ...,
     *   1/32), so that an iterate does not leave the basin of the stable
     *   branch; with the exact Jacobian du is a descent direction of |r|^2,
     *   so no decrease down to 1/32 fails the step at once.
     * - A step converges when |r| <= tol * max(|r_0|, |f_ext|, |f_int|).
     * - At every converged step the stability of the state is checked
     *   (StabilityInterface: the reduced tangent must be positive definite;
     *   Newton also converges to unstable equilibria, specs/001 §3.1).
     * - A step that does not converge in `Max iterations`, or converges to
     *   an unstable state, is cut: the increment times `Step cut factor`,
     *   down to `Max step cuts` cuts in a row (the paper cut by 10 then
     *   100, by hand); two successes in a row undo one cut. When the
     *   smallest increment fails the run stops with RunFailure("unstable")
     *   and outcome() says at which load; the solution is the last stable
     *   state, never a rejected iterate.
     */
    class NewtonDriver
    {
    public:
      /// d r / d t on the free DoFs at (u, t), r = f_ext - f_int: q for
      /// f_ext = t q, and -K_fp(u) d u_p / d t for prescribed values that
      /// move with t (hard loading).
      using LoadDerivative =
        std::function<void(const SystemInterface::Vector &u,
                           double                         t,
                           SystemInterface::Vector       &dr_dt)>;

      explicit NewtonDriver(const Settings &settings);

      /** A part of the load path for run(): where it starts and ends. */
      struct Span
      {
        /// The load factor of the equilibrium @p u the run starts from.
        double begin = 0.;
        /// The load factor it ends at.
        double end = 1.;
        /// The load increment before cuts (0: 1 / `Load steps`).
        double increment = 0.;
        /// The number of the first step's StepRecord.
        unsigned int first_step = 1;
        /// Follow the path past a failed smallest increment (see run());
        /// false: that failure ends the span (RunFailure "unstable").
        bool follow_snap_backs = true;
        /// After each on_step(): true ends the span at that state.
        std::function<bool(const StepRecord &)> stop_after;
        /// Before each on_step(), with @p u the converged state: true
        /// ends the span at the state before (which @p u then holds again),
        /// this one neither recorded nor accepted.
        std::function<bool(const StepRecord &)> stop_before;
        /// Checkpoint and restart: the loop state (the state before the
        /// last one, load factors, increment, cuts, outcome) is saved at
        /// the boundary after each recorded state; @p u must then be the
        /// checkpoint's solution.
        Resume resume;
      };

      /**
       * @p u: initial guess in, last stable state out. @p stability may be
       * null (no stability check). With @p load_derivative (loads linear
       * in t) a step that fails with the smallest increment is not the
       * end: the path is followed by arc length (as run_arc_length, the
       * last increment scaled to a full step as the arc length, at most
       * `Arc length steps`) until it reaches a stable state beyond the
       * failed load factor -- under displacement control the state the
       * body snaps to past a snap-back, where the path turns back in t --
       * and load control resumes there; only that state is reported
       * (on_step), the path's states are counted in outcome().
       */
      void
      run(SystemInterface                               &system,
          SystemInterface::Vector                       &u,
          const std::function<void(const StepRecord &)> &on_step,
          StabilityInterface                            *stability,
          const LoadDerivative                          &load_derivative = {});

      /**
       * As above over @p span only (the load factor from span.begin, the
       * state of @p u, to span.end, or to the first state for which
       * span.stop_after is true). Returns the load factor of the last
       * state, which @p u holds.
       */
      double
      run(SystemInterface                               &system,
          SystemInterface::Vector                       &u,
          const std::function<void(const StepRecord &)> &on_step,
          StabilityInterface                            *stability,
          const LoadDerivative                          &load_derivative,
          const Span                                    &span);

      const DriverTimings &
      timings() const
      {
        return time_spent;
      }

      /// Lines from inside a step (Newton iterations, the states of a
      /// snap-back path) through @p pulse.
      void
      set_progress(const ProgressPulse &pulse)
      {
        progress = pulse;
      }

      const NewtonOutcome &
      outcome() const
      {
        return result;
      }

      /**
       * Arc-length continuation (Crisfield's cylindrical constraint
       * |Delta u| = Delta l on the increment of a step), for soft loading
       * with f_ext(t) = t q and time-independent prescribed values: the load
       * factor becomes an unknown, so the path is followed through limit
       * points (folds, snap-backs) where load control stops 'unstable'.
       * The first step is load-controlled (1 / `Load steps`), its |Delta u|
       * sets Delta l; each step is a predictor along the tangent K^-1 q
       * (oriented by the previous increment) and Newton corrections with
       * the constraint (two solves per iteration, one factorisation); a
       * failing step halves Delta l (`Max step cuts` in a row). The run ends
       * when the load factor reaches 1, or after @p max_steps steps.
       * Every converged state is checked (StabilityReport in @p on_check,
       * not rejected: past a fold the path is unstable by nature). With
       * @p resume the run goes on from a checkpoint's state (u, the last
       * increment, the arc length, the load factor).
       */
      void
      run_arc_length(
        SystemInterface                                    &system,
        SystemInterface::Vector                            &u,
        const SystemInterface::Vector                      &q,
        unsigned int                                        max_steps,
        const std::function<void(const StepRecord &)>      &on_step,
        StabilityInterface                                 *stability,
        const std::function<void(const StabilityReport &)> &on_check = {});

      /**
       * Arc-length continuation for any load path r(u, t): soft loading
       * (f_ext = t q), hard loading (prescribed values u_p(t), written by
       * SystemInterface::apply_dirichlet at every iterate), or both. The
       * linearisation r + d r/d t dt - K du = 0 gives du = K^-1 r + dt
       * K^-1 d r/d t, as above with q replaced by @p load_derivative at the
       * current iterate; the constraint |Delta u| = Delta l is on the free
       * DoFs. Under displacement control this follows a snap-back (the
       * prescribed displacement decreasing while the crack grows), where
       * load-controlled Newton stops.
       */
      void
      run_arc_length(
        SystemInterface                                    &system,
        SystemInterface::Vector                            &u,
        const LoadDerivative                               &load_derivative,
        unsigned int                                        max_steps,
        const std::function<void(const StepRecord &)>      &on_step,
        StabilityInterface                                 *stability,
        const std::function<void(const StabilityReport &)> &on_check = {},
        const Resume                                       &resume   = {});

    private:
      /// One arc-length step from the converged (last, lambda): predictor
      /// along K^-1 dr/dt oriented by @p increment, Newton corrections
      /// with |u - last| = dl on the free DoFs (@p free_part zeroes the
      /// prescribed entries). True if converged; u, lam the new point.
      bool
      arc_step(SystemInterface               &system,
               SystemInterface::Vector       &u,
               double                        &lam,
               const SystemInterface::Vector &last,
               double                         lambda,
               const SystemInterface::Vector &increment,
               double                         dl,
               const LoadDerivative          &load_derivative,
               const std::function<void(SystemInterface::Vector &)> &free_part,
               StepRecord                                           &record);

      /// Newton at load factor t from u; true if converged.
      bool
      solve_step(SystemInterface         &system,
                 SystemInterface::Vector &u,
                 double                   t,
                 StepRecord              &record);

      Settings      settings;
      DriverTimings time_spent;
      NewtonOutcome result;
      ProgressPulse progress;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
