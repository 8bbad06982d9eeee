// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/drivers/static_driver.h>

#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "timing.h"

namespace pdfem
{
  namespace Drivers
  {
    using internal::clock;
    using internal::seconds_since;

    StepRecord
    equilibrate(SystemInterface         &system,
                SystemInterface::Vector &u,
                const double             t,
                const double             t_of_u,
                const unsigned int       step,
                const Settings          &settings,
                DriverTimings           &time_spent)
    {
      SystemInterface::Vector r, du;
      if (t_of_u > 0. && t != t_of_u)
        u *= t / t_of_u;
      system.apply_dirichlet(u, t);

      StepRecord record;
      record.step        = step;
      record.time        = t;
      record.load_factor = t;
      double reference   = 0.;
      for (unsigned int it = 0;; ++it)
        {
          auto         start  = clock::now();
          const bool   matrix = it < settings.max_iterations;
          const double norm   = system.residual(u, t, r, matrix);
          time_spent.assembly += seconds_since(start);
          if (!std::isfinite(norm))
            throw RunFailure("diverged",
                             "the residual is not finite at load step " +
                               std::to_string(step));
          if (it == 0)
            reference = std::max(norm, system.force_scale());
          const double scale       = std::max(reference, system.force_scale());
          record.relative_residual = scale > 0. ? norm / scale : norm;
          if (norm <= settings.residual_tolerance * scale ||
              (scale == 0. && norm == 0.))
            break;
          if (it == settings.max_iterations)
            {
              std::ostringstream s;
              s << "no equilibrium at load step " << step << " after " << it
                << " iterations (relative residual " << record.relative_residual
                << ")";
              throw RunFailure("diverged", s.str());
            }
          start = clock::now();
          // The linear solve need not go below what this loop accepts:
          // a tenth of the residual tolerance. After a crack step at held
          // load the residual is already small against the force scale,
          // and solving it to the solver's relative tolerance of |r|
          // cost a third of GMRES's iterations on the peer's plateCrack.
          record.linear_iterations += system.solve_linear_within(
            du, r, 0.1 * settings.residual_tolerance * scale);
          time_spent.solve += seconds_since(start);
          u += du;
          ++record.newton_iterations;
        }
      return record;
    }

    StaticDriver::StaticDriver(const Settings &settings)
      : settings(settings)
    {}

    void
    run_load_steps(
      const unsigned int                                             n_steps,
      const Resume                                                  &resume,
      const std::function<StepRecord(double, double, unsigned int)> &solve,
      const std::function<void(const StepRecord &)>                 &on_step)
    {
      const unsigned int first =
        resume.from ? resume.from->get<unsigned int>("driver/next step") : 1;
      for (unsigned int step = first; step <= n_steps; ++step)
        {
          if (step > first && resume.boundary)
            resume.boundary([step](StateArchive &state) {
              state.put("driver/next step", step);
            });
          on_step(
            solve(double(step) / n_steps, double(step - 1) / n_steps, step));
        }
    }

    void
    StaticDriver::run(SystemInterface                               &system,
                      SystemInterface::Vector                       &u,
                      const std::function<void(const StepRecord &)> &on_step,
                      const Resume                                  &resume)
    {
      run_load_steps(
        settings.load_steps,
        resume,
        [&](const double t, const double t_of_u, const unsigned int step) {
          return equilibrate(system, u, t, t_of_u, step, settings, time_spent);
        },
        on_step);
    }

    namespace
    {
      /// The `static` driver plugin: StaticDriver over the host's system;
      /// a criterion is evaluated after each step but grows nothing.
      class StaticRun : public Interface
      {
      public:
        void
        run(Host &host) override
        {
          driver = std::make_unique<StaticDriver>(parameters);
          driver->run(
            host.system(),
            host.solution(),
            [&host](const StepRecord &record) {
              host.after_equilibrium(record, false);
            },
            resume_through(host));
        }

        bool
        resumable() const override
        {
          return true;
        }

        bool
        handles_nonlinear_models() const override
        {
          return true; // Newton iterations without cuts or checks
        }

        bool
        solves_linear_systems() const override
        {
          return true;
        }

        bool
        solves_with_products() const override
        {
          return true; // equilibrate() uses the tangent in its solves only
        }

        std::map<std::string, double>
        timings() const override
        {
          return phase_timings(driver ? &driver->timings() : nullptr);
        }

      private:
        std::unique_ptr<StaticDriver> driver;
      };
    } // namespace

    PDFEM_REGISTER_DRIVER(StaticRun,
                          "static",
                          "equilibrium under the full load, reached in 'Load "
                          "steps' equal increments of the load factor t.")
  } // namespace Drivers
} // namespace pdfem
