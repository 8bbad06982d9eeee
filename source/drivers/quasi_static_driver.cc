// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/drivers/quasi_static_driver.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <sstream>

namespace pdfem
{
  namespace Drivers
  {
    QuasiStaticDriver::QuasiStaticDriver(const Parameters::Driver &settings)
      : settings(settings)
    {}

    void
    QuasiStaticDriver::run(
      const std::function<SystemInterface &()>             &system,
      SystemInterface::Vector                              &u,
      const std::function<GrowthCheck(const StepRecord &)> &after_step)
    {
      const double increment = settings.load_increment > 0. ?
                                 settings.load_increment :
                                 1. / settings.load_steps;
      double       t =
        settings.initial_load >= 0. ? settings.initial_load : increment;
      double t_of_u = 0.; // the load factor u is in equilibrium with
      for (unsigned int step = 1; step <= settings.load_steps; ++step)
        {
          const StepRecord record =
            equilibrate(system(), u, t, t_of_u, step, settings, time_spent);
          t_of_u                  = t;
          const GrowthCheck check = after_step(record);
          if (check.separated)
            {
              std::ostringstream s;
              s << "the body is cut through at step " << step
                << " (load factor " << t << ")";
              throw RunFailure("separated", s.str());
            }
          if (check.grew && settings.hold_load_while_growing)
            continue; // the load is held
          double       dt = increment;
          const double r  = 1.001 * check.critical_load_ratio;
          if (settings.jump_to_critical_load && t > 0. && std::isfinite(r) &&
              r > 1. && (r - 1.) * t < dt)
            dt = (r - 1.) * t;
          t += dt;
        }
    }
  } // namespace Drivers
} // namespace pdfem
