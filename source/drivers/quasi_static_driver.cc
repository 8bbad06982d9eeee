// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/drivers/quasi_static_driver.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <sstream>

namespace pdfem
{
  namespace Drivers
  {
    QuasiStaticDriver::QuasiStaticDriver(const Settings &settings)
      : settings(settings)
    {}

    void
    QuasiStaticDriver::run(
      const std::function<SystemInterface &()>             &system,
      SystemInterface::Vector                              &u,
      const std::function<GrowthCheck(const StepRecord &)> &after_step,
      const Resume                                         &resume)
    {
      const double increment = settings.load_increment > 0. ?
                                 settings.load_increment :
                                 1. / settings.load_steps;
      double       t =
        settings.initial_load >= 0. ? settings.initial_load : increment;
      double       t_of_u = 0.; // the load factor u is in equilibrium with
      unsigned int first  = 1;
      if (resume.from)
        {
          first  = resume.from->get<unsigned int>("driver/next step");
          t      = resume.from->get<double>("driver/load factor");
          t_of_u = resume.from->get<double>("driver/load factor of u");
        }
      for (unsigned int step = first; step <= settings.load_steps; ++step)
        {
          if (step > first && resume.boundary)
            resume.boundary([&](StateArchive &state) {
              state.put("driver/next step", step);
              state.put("driver/load factor", t);
              state.put("driver/load factor of u", t_of_u);
            });
          const StepRecord record =
            equilibrate(system(), u, t, t_of_u, step, settings, time_spent);
          t_of_u                  = t;
          const GrowthCheck check = after_step(record);
          if (check.separated)
            {
              std::ostringstream s;
              s << "the body is cut through at step " << step
                << " (load factor " << t << ")"
                << (check.separation.empty() ? "" : ": ") << check.separation;
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

    namespace
    {
      /// The `quasi-static` driver plugin: QuasiStaticDriver; the host's
      /// criterion grows cracks after each equilibrium.
      class QuasiStaticRun : public Interface
      {
      public:
        void
        run(Host &host) override
        {
          driver = std::make_unique<QuasiStaticDriver>(parameters);
          driver->run([&host]() -> SystemInterface & { return host.system(); },
                      host.solution(),
                      [&host](const StepRecord &record) {
                        return host.after_equilibrium(record, true);
                      },
                      resume_through(host));
        }

        bool
        resumable() const override
        {
          return true;
        }

        bool
        solves_linear_systems() const override
        {
          return true;
        }

        bool
        grows_cracks() const override
        {
          return true;
        }

        std::map<std::string, double>
        timings() const override
        {
          return phase_timings(driver ? &driver->timings() : nullptr);
        }

      private:
        std::unique_ptr<QuasiStaticDriver> driver;
      };
    } // namespace

    PDFEM_REGISTER_DRIVER(
      QuasiStaticRun,
      "quasi-static",
      "crack growth under a slowly increasing load: after each equilibrium "
      "the Fracture criterion is checked; where cracks grew the load is held "
      "and equilibrium found again, otherwise t grows by 'Load increment' "
      "('Load steps' steps in all).")
  } // namespace Drivers
} // namespace pdfem
