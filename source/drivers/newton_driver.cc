// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/drivers/newton_driver.h>

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace pdfem
{
  namespace Drivers
  {
    namespace
    {
      using clock = std::chrono::steady_clock;

      double
      seconds_since(const clock::time_point &start)
      {
        return std::chrono::duration<double>(clock::now() - start).count();
      }
    } // namespace

    NewtonDriver::NewtonDriver(const Parameters::Driver &settings)
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
      for (unsigned int it = 0;; ++it)
        {
          const double scale       = std::max(reference, system.force_scale());
          record.relative_residual = scale > 0. ? norm / scale : norm;
          if (norm <= settings.residual_tolerance * scale ||
              (scale == 0. && norm == 0.))
            return true;
          if (it == settings.max_iterations)
            return false;
          start = clock::now();
          record.linear_iterations += system.solve_linear(du, r);
          time_spent.solve += seconds_since(start);
          if (!std::isfinite(du.l2_norm()))
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
          u.swap(trial);
          r.swap(r_trial);
          norm = norm_trial;
        }
    }

    void
    NewtonDriver::run(SystemInterface                               &system,
                      SystemInterface::Vector                       &u,
                      const std::function<void(const StepRecord &)> &on_step,
                      StabilityInterface                            *stability)
    {
      result                       = NewtonOutcome();
      SystemInterface::Vector last = u, previous = u;
      double                  t = 0., t_previous = 0.;
      const double            base  = 1. / std::max(1u, settings.load_steps);
      double                  dt    = base;
      unsigned int            level = 0, successes = 0, step = 0;
      const double            t_end = 1. - 1e-12;
      while (t < t_end)
        {
          const double t_new = std::min(1., t + dt);
          // Predictor: the secant through the last two converged states
          // (the free DoFs follow the load instead of waiting for Newton).
          u = last;
          if (step > 0 && t > t_previous)
            {
              u.add((t_new - t) / (t - t_previous), last);
              u.add(-(t_new - t) / (t - t_previous), previous);
            }
          system.apply_dirichlet(u, t_new);
          StepRecord record;
          record.step        = step + 1;
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
          if (ok)
            {
              ++step;
              previous                = last;
              t_previous              = t;
              t                       = t_new;
              last                    = u;
              result.last_stable_load = t;
              on_step(record);
              // after two successes in a row, undo one cut
              if (level > 0 && ++successes == 2)
                {
                  --level;
                  dt        = std::min(base, dt / settings.step_cut_factor);
                  successes = 0;
                }
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
          // The smallest increment failed: unstable crack growth (or no
          // equilibrium at all).
          u                   = last;
          result.failure_load = t_new;
          std::ostringstream s;
          s << "unstable at load factor " << t_new << " (" << why << " with "
            << settings.max_step_cuts
            << " step cut(s)); last stable load factor " << t;
          throw RunFailure("unstable", s.str());
        }
    }
  } // namespace Drivers
} // namespace pdfem
