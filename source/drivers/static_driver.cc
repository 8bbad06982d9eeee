// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/drivers/static_driver.h>

#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace pdfem
{
  namespace Drivers
  {
    namespace
    {
      double
      seconds_since(const std::chrono::steady_clock::time_point &start)
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      }
    } // namespace

    StaticDriver::StaticDriver(const Parameters::Driver &settings)
      : settings(settings)
    {}

    void
    StaticDriver::run(SystemInterface                               &system,
                      SystemInterface::Vector                       &u,
                      const std::function<void(const StepRecord &)> &on_step,
                      std::ostream                                  *progress)
    {
      using clock = std::chrono::steady_clock;
      SystemInterface::Vector r, du;
      const auto              run_start = clock::now();
      const unsigned int      n_steps   = settings.load_steps;
      for (unsigned int step = 1; step <= n_steps; ++step)
        {
          const double t = double(step) / n_steps;
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
                reference = std::max(norm, system.external_force_norm());
              const double scale =
                std::max(reference, system.external_force_norm());
              record.relative_residual = scale > 0. ? norm / scale : norm;
              if (norm <= settings.residual_tolerance * scale ||
                  (scale == 0. && norm == 0.))
                break;
              if (it == settings.max_iterations)
                {
                  std::ostringstream s;
                  s << "no equilibrium at load step " << step << " after " << it
                    << " iterations (relative residual "
                    << record.relative_residual << ")";
                  throw RunFailure("diverged", s.str());
                }
              start = clock::now();
              record.linear_iterations += system.solve_linear(du, r);
              time_spent.solve += seconds_since(start);
              u += du;
              ++record.newton_iterations;
            }
          on_step(record);

          if (progress)
            {
              const double elapsed = seconds_since(run_start);
              const double left    = elapsed / step * (n_steps - step);
              *progress << "Step " << std::setw(4) << step << "/" << n_steps
                        << "  t = " << std::setw(8) << std::setprecision(4) << t
                        << "  iterations " << record.newton_iterations
                        << "  |r|/|f| = " << std::scientific
                        << std::setprecision(2) << record.relative_residual
                        << std::defaultfloat << "  left ~"
                        << std::setprecision(2) << std::fixed << left << " s"
                        << std::defaultfloat << std::endl;
            }
        }
    }
  } // namespace Drivers
} // namespace pdfem
