// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the drivers module: what the explicit and newmark driver
// plugins share.
#ifndef PDFEM_SOURCE_DRIVERS_TIME_INTEGRATION_RUN_H
#define PDFEM_SOURCE_DRIVERS_TIME_INTEGRATION_RUN_H

#include <pdfem/base/exceptions.h>
#include <pdfem/drivers/interface.h>

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <memory>

namespace pdfem
{
  namespace Drivers
  {
    /**
     * A driver plugin that integrates in time with @p Integrator
     * (CentralDifference or Newmark): it needs a mass, grows cracks after
     * every step through the host's criterion, and reports the integrator's
     * timings per step; it resumes from checkpoints (the integrator saves
     * its loop state, Drivers::Resume).
     */
    template <class Integrator>
    class TimeIntegrationRun : public Interface
    {
    public:
      bool
      dynamic() const override
      {
        return true;
      }

      bool
      grows_cracks() const override
      {
        return true; // the criterion runs after every time step
      }

      void
      check(const RunTraits &traits) const override
      {
        Interface::check(traits);
        if (!traits.has_mass)
          throw InputError(traits.file,
                           "Material/Density",
                           "the density is not positive, and a dynamic run "
                           "(Driver/Type = " +
                             traits.driver_name + ") needs a mass",
                           "rho > 0 [kg/m^3]");
      }

      std::map<std::string, double>
      timings() const override
      {
        const DynamicTimings &t =
          integrator ? integrator->timings() : DynamicTimings();
        const double n = std::max(1u, t.n_steps);
        return {{"assembly", t.internal_force + t.external_force + t.factorize},
                {"solve", t.solve + t.update},
                {"time_loop", t.steps},
                {"seconds_per_step", t.steps / n},
                {"internal_force_per_step", t.internal_force / n},
                {"external_force_per_step", t.external_force / n},
                {"update_per_step", t.update / n},
                {"solve_per_step", t.solve / n},
                {"factorize", t.factorize},
                {"eigenvalue", t.eigenvalue}};
      }

      bool
      resumable() const override
      {
        return true;
      }

      void
      run(Host &host) override
      {
        integrate(host, resume_through(host));
      }

    protected:
      /// Make the integrator and run it over the host's system, from the
      /// host's initial velocity and the checkpoint's state (@p resume).
      void
      integrate(Host &host, const Resume &resume)
      {
        integrator = std::make_unique<Integrator>(parameters);
        SystemInterface::Vector v0;
        host.initial_velocity(v0);
        integrator->run(
          host.dynamic_system(),
          host.solution(),
          v0,
          [&host](const DynamicRecord &record) {
            host.record_time_step(record);
          },
          [&host](const SystemInterface::Vector &u, const double t) {
            return host.after_time_step(u, t);
          },
          resume);
      }

      std::unique_ptr<Integrator> integrator;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
