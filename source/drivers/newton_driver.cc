// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/drivers/newton_driver.h>

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>

#include "timing.h"

namespace pdfem
{
  namespace Drivers
  {
    namespace
    {
      using internal::clock;
      using internal::seconds_since;

      /**
       * Solve K x = b with the last tangent; false (x not finite) where the
       * linear solver fails: a singular tangent at a limit point of a
       * softening model is a failed step like one that does not converge
       * (the step is cut, or the path followed past the point). Other
       * failures propagate. Adds the linear iterations to @p iterations.
       */
      bool
      solve_or_fail(SystemInterface               &system,
                    SystemInterface::Vector       &x,
                    const SystemInterface::Vector &b,
                    unsigned int                  *iterations       = nullptr,
                    const double                   allowed_residual = 0.)
      {
        try
          {
            const unsigned int n =
              system.solve_linear_within(x, b, allowed_residual);
            if (iterations != nullptr)
              *iterations += n;
          }
        catch (const RunFailure &failure)
          {
            if (failure.exit_state != "singular matrix" &&
                failure.exit_state != "linear solver diverged")
              throw;
            return false;
          }
        return std::isfinite(x.l2_norm());
      }

      /// Inexact Newton's forcing terms (Eisenstat & Walker 1996, choice 2,
      /// gamma 0.9, alpha 2, safeguarded, at most 0.1): an iterative solve of
      /// iteration k stops at eta_k |r_k| (theory.md §13.7).
      constexpr double largest_forcing = 0.1;

      double
      next_forcing(const double previous, const double residual_ratio)
      {
        double eta = 0.9 * residual_ratio * residual_ratio;
        if (0.9 * previous * previous > 0.1)
          eta = std::max(eta, 0.9 * previous * previous);
        return std::min(eta, largest_forcing);
      }

      /// v -> v with its prescribed entries zeroed: apply_dirichlet(v, 0)
      /// writes u_p(0) into them, and p0 holds u_p(0) there and 0 elsewhere.
      std::function<void(SystemInterface::Vector &)>
      free_part_of(SystemInterface &system)
      {
        auto p0 = std::make_shared<SystemInterface::Vector>();
        system.initialize_vector(*p0);
        system.apply_dirichlet(*p0, 0.);
        return [&system, p0](SystemInterface::Vector &v) {
          system.apply_dirichlet(v, 0.);
          v -= *p0;
        };
      }
    } // namespace

    NewtonDriver::NewtonDriver(const Settings &settings)
      : settings(settings)
    {}

    bool
    NewtonDriver::solve_step(SystemInterface         &system,
                             SystemInterface::Vector &u,
                             const double             t,
                             StepRecord              &record)
    {
      SystemInterface::Vector r, du, trial, r_trial;
      system.initialize_vector(du);
      system.initialize_vector(trial);
      system.initialize_vector(r_trial);
      system.initialize_vector(r);
      auto   start = clock::now();
      double norm  = system.residual(u, t, r, true);
      time_spent.assembly += seconds_since(start);
      if (!std::isfinite(norm))
        return false;
      const double reference = std::max(norm, system.force_scale());
      double       forcing   = largest_forcing;
      for (unsigned int it = 0;; ++it)
        {
          const double scale       = std::max(reference, system.force_scale());
          record.relative_residual = scale > 0. ? norm / scale : norm;
          if (norm <= settings.residual_tolerance * scale ||
              (scale == 0. && norm == 0.))
            return true;
          progress([&]() {
            std::ostringstream s;
            s << "  load factor " << t << ": Newton iteration " << it
              << ", |r|/|f| = " << record.relative_residual;
            return s.str();
          });
          if (it == settings.max_iterations)
            return false;
          start = clock::now();
          // Inexact Newton: an iterative solve stops at forcing * |r|, and
          // never needs to go below a tenth of the residual this loop
          // accepts. A direct solve is exact and ignores both.
          const bool ok =
            solve_or_fail(system,
                          du,
                          r,
                          &record.linear_iterations,
                          std::max(forcing * norm,
                                   0.1 * settings.residual_tolerance * scale));
          time_spent.solve += seconds_since(start);
          if (!ok)
            return false;
          ++record.newton_iterations;

          // Backtracking on |r|; the trial residual assembles the tangent,
          // which is the next iteration's when the trial is accepted.
          double alpha = 1., norm_trial = 0.;
          for (unsigned int cut = 0;; ++cut)
            {
              trial = u;
              trial.add(alpha, du);
              start      = clock::now();
              norm_trial = system.residual(trial, t, r_trial, true);
              time_spent.assembly += seconds_since(start);
              const bool decrease =
                std::isfinite(norm_trial) &&
                (norm_trial <= (1. - 1e-4 * alpha) * norm ||
                 norm_trial <= settings.residual_tolerance *
                                 std::max(reference, system.force_scale()));
              if (decrease || !settings.line_search)
                break;
              // With the exact Jacobian du is a descent direction of |r|^2:
              // no decrease down to a = 1/32 means K is (nearly) singular
              // or the load is past the end of the branch.
              if (cut == 5)
                return false;
              alpha *= 0.5;
            }
          if (!std::isfinite(norm_trial))
            return false;
          forcing = next_forcing(forcing, norm_trial / norm);
          u.swap(trial);
          r.swap(r_trial);
          norm = norm_trial;
        }
    }

    void
    NewtonDriver::run(SystemInterface                               &system,
                      SystemInterface::Vector                       &u,
                      const std::function<void(const StepRecord &)> &on_step,
                      StabilityInterface                            *stability,
                      const LoadDerivative &load_derivative)
    {
      run(system, u, on_step, stability, load_derivative, Span());
    }

    double
    NewtonDriver::run(SystemInterface                               &system,
                      SystemInterface::Vector                       &u,
                      const std::function<void(const StepRecord &)> &on_step,
                      StabilityInterface                            *stability,
                      const LoadDerivative &load_derivative,
                      const Span           &span)
    {
      result                            = NewtonOutcome();
      const auto              free_part = free_part_of(system);
      SystemInterface::Vector last = u, previous = u;
      double                  t = span.begin, t_previous = span.begin;
      const double            base  = span.increment > 0. ?
                                        span.increment :
                                        1. / std::max(1u, settings.load_steps);
      double                  dt    = base;
      unsigned int            level = 0, successes = 0, step = 0;
      const double            t_end = span.end - 1e-12;
      if (span.resume.from)
        {
          // u is the checkpoint's solution, the last recorded state.
          const StateArchive &state = *span.resume.from;
          state.get_owned("driver/previous", previous);
          t          = state.get<double>("driver/load factor");
          t_previous = state.get<double>("driver/previous load factor");
          dt         = state.get<double>("driver/increment");
          level      = state.get<unsigned int>("driver/cuts");
          successes  = state.get<unsigned int>("driver/successes");
          step       = state.get<unsigned int>("driver/steps");
          result     = state.get<NewtonOutcome>("driver/outcome");
        }
      const auto save = [&](StateArchive &state) {
        state.put_owned("driver/previous", previous);
        state.put("driver/load factor", t);
        state.put("driver/previous load factor", t_previous);
        state.put("driver/increment", dt);
        state.put("driver/cuts", level);
        state.put("driver/successes", successes);
        state.put("driver/steps", step);
        state.put("driver/outcome", result);
      };
      // A state was recorded since the last step boundary.
      bool recorded = false;
      while (t < t_end)
        {
          if (recorded && span.resume.boundary)
            span.resume.boundary(save);
          recorded           = false;
          const double t_new = std::min(span.end, t + dt);
          // Predictor: the secant through the last two converged states
          // (the free DoFs follow the load instead of waiting for Newton).
          u = last;
          if (step > 0 && t > t_previous)
            {
              u.add((t_new - t) / (t - t_previous), last);
              u.add(-(t_new - t) / (t - t_previous), previous);
            }
          else if (load_derivative)
            {
              // no secant yet: the tangent, u + (t_new - t) K^-1 dr/dt (under
              // hard loading the prescribed values alone would stretch the
              // bonds next to the boundary layer far into softening)
              SystemInterface::Vector r, q, dq;
              system.initialize_vector(r);
              system.initialize_vector(q);
              system.residual(u, t, r, true);
              load_derivative(u, t, q);
              if (solve_or_fail(system, dq, q))
                u.add(t_new - t, dq);
            }
          system.apply_dirichlet(u, t_new);
          StepRecord record;
          record.step        = span.first_step + step;
          record.time        = t_new;
          record.load_factor = t_new;
          bool        ok     = solve_step(system, u, t_new, record);
          std::string why    = ok ? "" : "no equilibrium";
          if (ok && stability != nullptr && settings.stability_check)
            {
              const auto start  = clock::now();
              result.last_check = stability->check_stability();
              time_spent.solve += seconds_since(start);
              if (!result.last_check.stable())
                {
                  ok = false;
                  ++result.n_unstable_states;
                  std::ostringstream s;
                  s << "the equilibrium is not stable (tangent "
                    << (result.last_check.singular ?
                          std::string("singular") :
                          std::to_string(result.last_check.n_negative) +
                            " negative eigenvalue(s)")
                    << ")";
                  why = s.str();
                }
            }
          if (ok && span.stop_before && span.stop_before(record))
            {
              u = last;
              return t;
            }
          if (ok)
            {
              ++step;
              previous                = last;
              t_previous              = t;
              t                       = t_new;
              last                    = u;
              result.last_stable_load = t;
              on_step(record);
              progress.restart();
              if (span.stop_after && span.stop_after(record))
                return t;
              // after two successes in a row, undo one cut
              if (level > 0 && ++successes == 2)
                {
                  --level;
                  dt        = std::min(base, dt / settings.step_cut_factor);
                  successes = 0;
                }
              recorded = true;
              continue;
            }
          successes = 0;
          if (level < settings.max_step_cuts)
            {
              ++level;
              ++result.n_cuts;
              dt *= settings.step_cut_factor;
              continue;
            }
          // The smallest increment failed. With loads linear in t, follow
          // the equilibrium path by arc length from the last stable state
          // (a snap-back under displacement control: the path turns back in
          // t through unstable states) until it reaches a stable state
          // beyond the failed load factor, the state the body jumps to;
          // load control resumes there.
          if (span.follow_snap_backs && load_derivative &&
              stability != nullptr && settings.stability_check && step > 0 &&
              t > t_previous)
            {
              SystemInterface::Vector first_increment = last;
              first_increment -= previous;
              free_part(first_increment);
              // Two tries. First a short arc, the last (smallest)
              // increment: a longer one can jump from the fold onto other,
              // unstable branches; easy steps lengthen it. If that path
              // does not come back (it can wander along unstable branches),
              // the last increment scaled to a full load step, which jumps
              // across small snap-backs directly.
              const double dl_short = first_increment.l2_norm();
              const double dl_long  = dl_short * base / (t - t_previous);
              bool         passed   = false;
              double       lambda   = t;
              for (const double dl0 : {dl_short, dl_long})
                {
                  SystemInterface::Vector increment = first_increment,
                                          path_last = last;
                  double dl                         = dl0;
                  lambda                            = t;
                  for (unsigned int k = 0, cuts = 0;
                       k < settings.arc_length_steps && dl > 0.;)
                    {
                      StepRecord path;
                      double     lam;
                      if (!arc_step(system,
                                    u,
                                    lam,
                                    path_last,
                                    lambda,
                                    increment,
                                    dl,
                                    load_derivative,
                                    free_part,
                                    path))
                        {
                          // next to the fold K_ff is nearly singular: the
                          // corrector may need a much shorter arc
                          if (++cuts > std::max(settings.max_step_cuts, 8u))
                            break;
                          dl *= 0.5;
                          continue;
                        }
                      cuts = 0;
                      ++k;
                      ++result.n_path_states;
                      progress([&]() {
                        std::ostringstream s;
                        s << "  following the path past the fold at load "
                             "factor "
                          << t << ": state " << k << ", load factor " << lam;
                        return s.str();
                      });
                      // easy steps lengthen the arc: the unstable part of
                      // the path can be long compared with the last step
                      if (path.newton_iterations <= 3)
                        dl *= 1.5;
                      increment = u;
                      increment -= path_last;
                      free_part(increment);
                      path_last         = u;
                      lambda            = lam;
                      result.last_check = stability->check_stability();
                      if (!result.last_check.stable())
                        ++result.n_unstable_states;
                      else if (lambda > t_new)
                        {
                          passed = true;
                          break;
                        }
                    }
                  if (passed)
                    break;
                }
              if (passed)
                {
                  ++result.n_snap_backs;
                  ++step;
                  previous                = u;
                  t_previous              = lambda;
                  t                       = lambda;
                  last                    = u;
                  result.last_stable_load = t;
                  record.step             = span.first_step + step - 1;
                  record.time = record.load_factor = t;
                  on_step(record);
                  if (span.stop_after && span.stop_after(record))
                    return t;
                  level     = 0;
                  dt        = base;
                  successes = 0;
                  recorded  = true;
                  continue;
                }
            }
          // unstable crack growth (or no equilibrium at all)
          u                   = last;
          result.failure_load = t_new;
          std::ostringstream s;
          s << "unstable at load factor " << t_new << " (" << why << " with "
            << settings.max_step_cuts
            << " step cut(s)); last stable load factor " << t;
          throw RunFailure("unstable", s.str());
        }
      return t;
    }

    bool
    NewtonDriver::arc_step(
      SystemInterface                                      &system,
      SystemInterface::Vector                              &u,
      double                                               &lam,
      const SystemInterface::Vector                        &last,
      const double                                          lambda,
      const SystemInterface::Vector                        &increment,
      const double                                          dl,
      const LoadDerivative                                 &load_derivative,
      const std::function<void(SystemInterface::Vector &)> &free_part,
      StepRecord                                           &record)
    {
      SystemInterface::Vector r, dq, dr, w, q;
      system.initialize_vector(r);
      system.initialize_vector(dq);
      system.initialize_vector(dr);
      system.initialize_vector(q);
      // predictor along K^-1 dr/dt (K of the last converged state)
      system.residual(last, lambda, r, true);
      load_derivative(last, lambda, q);
      if (!solve_or_fail(system, dq, q))
        return false;
      const double sign = (dq * increment) >= 0. ? 1. : -1.;
      const double dlam = sign * dl / dq.l2_norm();
      u                 = last;
      u.add(dlam, dq);
      lam = lambda + dlam;
      system.apply_dirichlet(u, lam);
      double ref = 0.;
      for (unsigned int it = 0; it <= settings.max_iterations; ++it)
        {
          const double norm = system.residual(u, lam, r, true);
          if (!std::isfinite(norm))
            return false;
          const double scale = std::max(system.force_scale(), ref);
          if (it == 0)
            ref = std::max(norm, system.force_scale());
          record.relative_residual = scale > 0. ? norm / scale : norm;
          if (norm <= settings.residual_tolerance * scale)
            return true;
          if (it == settings.max_iterations)
            return false;
          load_derivative(u, lam, q);
          if (!solve_or_fail(system, dr, r) || !solve_or_fail(system, dq, q))
            return false;
          // |Delta u + dr + dlam dq| = dl, Delta u = u - last (free DoFs:
          // dr and dq vanish on the prescribed ones)
          w = u;
          w -= last;
          w += dr;
          free_part(w);
          const double a = dq * dq, b = 2. * (dq * w), c = w * w - dl * dl;
          const double disc = b * b - 4. * a * c;
          if (!(disc >= 0.) || !(a > 0.))
            return false;
          const double x1 = (-b + std::sqrt(disc)) / (2. * a);
          const double x2 = (-b - std::sqrt(disc)) / (2. * a);
          // the root that keeps the increment closest to the last one
          w.add(x1, dq);
          const double c1 = w * increment;
          w.add(x2 - x1, dq);
          const double c2 = w * increment;
          const double d  = c1 >= c2 ? x1 : x2;
          u += dr;
          u.add(d, dq);
          lam += d;
          system.apply_dirichlet(u, lam);
          ++record.newton_iterations;
          record.linear_iterations += 2;
        }
      return false;
    }

    void
    NewtonDriver::run_arc_length(
      SystemInterface                                    &system,
      SystemInterface::Vector                            &u,
      const SystemInterface::Vector                      &q,
      const unsigned int                                  max_steps,
      const std::function<void(const StepRecord &)>      &on_step,
      StabilityInterface                                 *stability,
      const std::function<void(const StabilityReport &)> &on_check)
    {
      run_arc_length(
        system,
        u,
        [&q](const SystemInterface::Vector &,
             double,
             SystemInterface::Vector &dr_dt) { dr_dt = q; },
        max_steps,
        on_step,
        stability,
        on_check);
    }

    void
    NewtonDriver::run_arc_length(
      SystemInterface                                    &system,
      SystemInterface::Vector                            &u,
      const LoadDerivative                               &load_derivative,
      const unsigned int                                  max_steps,
      const std::function<void(const StepRecord &)>      &on_step,
      StabilityInterface                                 *stability,
      const std::function<void(const StabilityReport &)> &on_check,
      const Resume                                       &resume)
    {
      result = NewtonOutcome();
      SystemInterface::Vector r, dq, dr, w, q, last = u, increment;
      system.initialize_vector(r);
      system.initialize_vector(dq);
      system.initialize_vector(dr);
      system.initialize_vector(q);
      // The constraint measures the free DoFs only.
      const auto   free_part = free_part_of(system);
      double       dl = 0., lambda = 0.;
      unsigned int step = 2;
      // A point was recorded since the last step boundary.
      bool recorded = false;
      if (resume.from)
        {
          // u is the checkpoint's solution, the last converged point.
          const StateArchive &state = *resume.from;
          system.initialize_vector(increment);
          state.get_owned("driver/increment", increment);
          dl     = state.get<double>("driver/arc length");
          lambda = state.get<double>("driver/load factor");
          step   = state.get<unsigned int>("driver/next step");
          result = state.get<NewtonOutcome>("driver/outcome");
        }
      else
        {
          // ---- first step: load control
          StepRecord   first;
          const double t0 = 1. / std::max(1u, settings.load_steps);
          first.step      = 1;
          first.time = first.load_factor = t0;
          // tangent predictor u + t0 K^-1 dr/dt: under hard loading, the
          // prescribed values alone would stretch the bonds next to the
          // boundary layer far into softening
          system.residual(u, 0., r, true);
          load_derivative(u, 0., q);
          system.solve_linear(dq, q);
          u.add(t0, dq);
          system.apply_dirichlet(u, t0);
          if (!solve_step(system, u, t0, first))
            throw RunFailure("diverged",
                             "arc length: the first, load-controlled step "
                             "does not converge");
          increment = u;
          increment -= last;
          free_part(increment);
          dl                      = increment.l2_norm();
          lambda                  = t0;
          last                    = u;
          result.last_stable_load = lambda;
          if (stability != nullptr && on_check)
            on_check(stability->check_stability());
          on_step(first);
          recorded = true;
        }
      const auto save = [&](StateArchive &state) {
        state.put_owned("driver/increment", increment);
        state.put("driver/arc length", dl);
        state.put("driver/load factor", lambda);
        state.put("driver/next step", step);
        state.put("driver/outcome", result);
      };

      unsigned int level = 0;
      while (step <= max_steps && lambda < 1.)
        {
          if (recorded && resume.boundary)
            resume.boundary(save);
          recorded = false;
          StepRecord record;
          record.step = step;
          double     lam;
          const bool ok = arc_step(system,
                                   u,
                                   lam,
                                   last,
                                   lambda,
                                   increment,
                                   dl,
                                   load_derivative,
                                   free_part,
                                   record);
          if (!ok)
            {
              if (level == settings.max_step_cuts)
                {
                  u                   = last;
                  result.failure_load = lam;
                  throw RunFailure("diverged",
                                   "arc length: no convergence with the "
                                   "smallest arc length");
                }
              ++level;
              ++result.n_cuts;
              dl *= 0.5;
              continue;
            }
          level     = 0;
          increment = u;
          increment -= last;
          free_part(increment);
          last        = u;
          lambda      = lam;
          record.time = record.load_factor = lambda;
          if (stability != nullptr)
            {
              result.last_check = stability->check_stability();
              if (result.last_check.stable())
                result.last_stable_load =
                  std::max(result.last_stable_load, lambda);
              else
                ++result.n_unstable_states;
              if (on_check)
                on_check(result.last_check);
            }
          on_step(record);
          progress.restart();
          ++step;
          recorded = true;
        }
    }

    namespace
    {
      /// What the newton and arc length plugins share.
      class NonlinearRun : public Interface
      {
      public:
        void
        initialize(const Settings    &settings,
                   const std::string &file,
                   const int          dim) override
        {
          Interface::initialize(settings, file, dim);
          input_file = file;
        }

        bool
        handles_nonlinear_models() const override
        {
          return true;
        }

        bool
        solves_linear_systems() const override
        {
          return true;
        }

        void
        check(const RunTraits &traits) const override
        {
          if (!traits.nonlinear_model)
            throw InputError(traits.file,
                             "Driver/Type",
                             "the " + traits.driver_name +
                               " driver is for nonlinear models; the " +
                               traits.model_name + " model is linear",
                             "static or quasi-static, or a nonlinear model "
                             "(Peridynamics/Model = rnp)");
        }

        std::map<std::string, double>
        timings() const override
        {
          return phase_timings(driver ? &driver->timings() : nullptr);
        }

        const NewtonOutcome *
        outcome() const override
        {
          return driver ? &driver->outcome() : nullptr;
        }

        bool
        resumable() const override
        {
          return true;
        }

      protected:
        std::unique_ptr<NewtonDriver> driver;
        std::string                   input_file;
      };

      /// The `newton` driver plugin: load stepping with line search, step
      /// cuts and the stability check; the snap-back continuation under
      /// hard loading where the host offers it.
      class NewtonRun : public NonlinearRun
      {
      public:
        void
        run(Host &host) override
        {
          driver = std::make_unique<NewtonDriver>(parameters);
          driver->set_progress(host.progress_pulse());
          // Each recorded state passed the stability check (when there is
          // one): the host hears of it before the state.
          const bool checked =
            parameters.stability_check && host.stability() != nullptr;
          NewtonDriver::Span span;
          span.resume = resume_through(host);
          driver->run(
            host.system(),
            host.solution(),
            [this, &host, checked](const StepRecord &record) {
              if (checked)
                host.after_stability_check(driver->outcome().last_check);
              host.after_equilibrium(record, false);
            },
            host.stability(),
            host.load_derivative(false),
            span);
        }
      };

      /// The `arc length` driver plugin: Crisfield's continuation.
      class ArcLengthRun : public NonlinearRun
      {
      public:
        void
        run(Host &host) override
        {
          const NewtonDriver::LoadDerivative dr_dt = host.load_derivative(true);
          if (!dr_dt)
            throw InputError(input_file,
                             "Driver/Type",
                             "arc length needs loads linear in t (tractions "
                             "and body force t q, prescribed values u_p(0) + "
                             "t w)",
                             "such loads, or the newton driver");
          driver = std::make_unique<NewtonDriver>(parameters);
          driver->set_progress(host.progress_pulse());
          driver->run_arc_length(
            host.system(),
            host.solution(),
            dr_dt,
            parameters.arc_length_steps,
            [&host](const StepRecord &record) {
              host.after_equilibrium(record, false);
            },
            host.stability(),
            [&host](const StabilityReport &report) {
              host.after_stability_check(report);
            },
            resume_through(host));
        }
      };
    } // namespace

    PDFEM_REGISTER_DRIVER(
      NewtonRun,
      "newton",
      "static stepping with a line search, load step cutting and a stability "
      "check of every converged step (nonlinear models: rnp); a step that "
      "cannot be completed stops the run with exit state 'unstable'.")
    PDFEM_REGISTER_DRIVER(
      ArcLengthRun,
      "arc length",
      "the load factor becomes an unknown (Crisfield's arc-length "
      "continuation), so the path is followed through limit points and "
      "snap-backs; loads linear in t only (rnp).")
  } // namespace Drivers
} // namespace pdfem
