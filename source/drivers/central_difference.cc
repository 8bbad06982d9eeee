// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/central_difference.h>
#include <pdfem/drivers/interface.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dynamics_internal.h"
#include "time_integration_run.h"

namespace pdfem
{
  namespace Drivers
  {
    using namespace internal;

    CentralDifference::CentralDifference(const Settings &settings)
      : settings(settings)
    {}

    void
    CentralDifference::check_time_step()
    {
      dt = settings.time_step > 0. ?
             settings.time_step :
             settings.safety_factor * estimate.critical_time_step;
      if (!(dt > 0.))
        throw RunFailure("time step too large",
                         "no stable time step: the largest eigenvalue of "
                         "M^-1 K is not positive (no free DoF?)");
      // A given step above the critical one is refused before the first
      // step, however few steps the run has (the estimate from below of
      // omega_max makes dt_crit an upper bound: no stable step is refused).
      if (settings.time_step > estimate.critical_time_step)
        throw RunFailure(
          "time step too large",
          "Driver/Time step = " + number(settings.time_step) +
            " s is above the critical step 2/omega_max = " +
            number(estimate.critical_time_step) +
            " s of this mesh: the central difference would blow up; use at "
            "most " +
            number(0.9 * estimate.critical_time_step) +
            " s (or Time step = auto)");
    }

    void
    CentralDifference::run(DynamicSystemInterface &system,
                           Vector                 &U,
                           const Vector           &v0,
                           const OnStep           &on_step,
                           const AfterStep        &after_step,
                           const Resume           &resume)
    {
      auto start = clock::now();
      if (resume.from)
        {
          // The step and its estimate as they were: a power iteration now
          // would see the broken bonds and give another step.
          estimate = resume.from->get<StabilityEstimate>("driver/estimate");
          dt       = resume.from->get<double>("driver/time step");
        }
      else
        {
          estimate =
            estimate_stable_time_step(system, settings.eigenvalue_iterations);
          time_spent.eigenvalue = seconds_since(start);
          check_time_step();
        }
      const unsigned int n_steps =
        static_cast<unsigned int>(std::ceil(settings.end_time / dt - 1e-9));
      const MPI_Comm comm = U.get_mpi_communicator();

      const Vector &M = system.lumped_mass();
      Vector        V, A, F_int, F_ext;
      system.initialize_vector(V);
      system.initialize_vector(A);
      system.initialize_vector(F_int);
      system.initialize_vector(F_ext);
      std::vector<char>   held = held_flags(system, U);
      const std::size_t   n    = held.size();
      std::vector<double> held_old;
      // Half-step velocities of this and the last step: their correlation
      // tells a time-step instability (out of phase) from a growing mode.
      std::vector<double> half(n, 0.), half_old(n, 0.);

      const double *m            = M.begin();
      auto          acceleration = [&]() {
        double       *a  = A.begin();
        const double *fi = F_int.begin();
        const double *fe = F_ext.begin();
        for (std::size_t i = 0; i < n; ++i)
          a[i] = held[i] ? 0. : (fe[i] - fi[i]) / m[i];
      };
      auto kinetic = [&]() {
        const double *v     = V.begin();
        double        local = 0.;
        for (std::size_t i = 0; i < n; ++i)
          if (!held[i])
            local += m[i] * v[i] * v[i];
        return 0.5 * dealii::Utilities::MPI::sum(local, comm);
      };
      EnergyAccount  energy;
      LeapfrogEnergy conserved;
      DynamicRecord  record;
      unsigned int   first = 1;
      TimeLoopState  loop{V, A, F_int, F_ext, held, energy};
      if (resume.from)
        {
          // Everything the loop carries from one step to the next, as it
          // was at the checkpoint.
          const StateArchive &state = *resume.from;
          first                     = loop.load(state, U);
          half                      = state.get_vector<double>("driver/half");
          half_old = state.get_vector<double>("driver/half old");
          if (half.size() != n || half_old.size() != n)
            throw InputError("",
                             "--restart",
                             "the checkpoint's explicit state does not fit "
                             "this run's vectors");
          conserved.load(state, "driver/leapfrog/", U);
        }
      else
        {
          // t = 0: prescribed values, initial velocity on the free DoFs.
          system.apply_dirichlet(U, 0.);
          V = v0;
          system.internal_force(U, F_int);
          system.external_force(0., F_ext);
          {
            double *v = V.begin();
            for (std::size_t i = 0; i < n; ++i)
              if (held[i])
                v[i] = 0.;
          }
          acceleration();
          energy.start(U, F_int, F_ext, held, kinetic(), comm);
          conserved.start(U, comm);
          record.time_step = dt;
          energy.record(record);
          on_step(record);
        }
      const auto save = [&](StateArchive &state, const unsigned int step) {
        loop.save(state, step);
        state.put("driver/estimate", estimate);
        state.put("driver/time step", dt);
        state.put("driver/half", half);
        state.put("driver/half old", half_old);
        conserved.save(state, "driver/leapfrog/");
      };

      const auto loop_start = clock::now();
      for (unsigned int step = first; step <= n_steps; ++step)
        {
          if (step > first && resume.boundary)
            resume.boundary([&](StateArchive &state) { save(state, step); });
          // The last step ends at the end time exactly (it is shorter).
          const bool   last = step == n_steps;
          const double h = last ? settings.end_time - (n_steps - 1) * dt : dt;
          const double t = last ? settings.end_time : step * dt;
          start          = clock::now();
          {
            double       *u = U.begin();
            double       *v = V.begin();
            const double *a = A.begin();
            held_old.clear();
            for (std::size_t i = 0; i < n; ++i)
              if (held[i])
                held_old.push_back(u[i]);
              else
                {
                  v[i] += 0.5 * h * a[i];
                  u[i] += h * v[i];
                }
            half.swap(half_old);
            std::copy(v, v + n, half.begin());
          }
          system.apply_dirichlet(U, t);
          time_spent.update += seconds_since(start);

          start = clock::now();
          system.internal_force(U, F_int);
          time_spent.internal_force += seconds_since(start);
          start = clock::now();
          system.external_force(t, F_ext);
          time_spent.external_force += seconds_since(start);

          start = clock::now();
          acceleration();
          {
            double       *v = V.begin();
            const double *a = A.begin();
            for (std::size_t i = 0; i < n; ++i)
              if (!held[i])
                v[i] += 0.5 * h * a[i];
          }
          energy.step(U, F_int, F_ext, held, kinetic());
          // The shortened last step is outside the leapfrog identity.
          const bool uniform = h == dt;
          if (uniform)
            conserved.step(U, half, M, F_int, F_ext, held);
          time_spent.update += seconds_since(start);

          record           = DynamicRecord();
          record.step      = step;
          record.time      = t;
          record.time_step = h;
          if (after_step)
            {
              start              = clock::now();
              record.bonds_broke = after_step(U, t);
              if (!record.bonds_broke)
                {
                  // A model whose forces changed at fixed u without broken
                  // bonds (lps fft's failed nodes, one step late as in the
                  // paper): the strain energy it released is dissipated.
                  const double released = system.released_energy();
                  if (released != 0.)
                    {
                      energy.released(released);
                      if (uniform)
                        conserved.released(released);
                    }
                }
              else
                {
                  // Forces at the same u with the new bonds: the released
                  // strain energy is dissipated; a^n+1 and the second half
                  // of v^n+1 are redone with them.
                  double       *v = V.begin();
                  const double *a = A.begin();
                  for (std::size_t i = 0; i < n; ++i)
                    if (!held[i])
                      v[i] -= 0.5 * h * a[i];
                  held = held_flags(system, U);
                  system.internal_force(U, F_int);
                  energy.bonds_broke(U, F_int);
                  if (uniform)
                    conserved.bonds_broke(F_int, F_ext, held);
                  acceleration();
                  a = A.begin();
                  for (std::size_t i = 0; i < n; ++i)
                    if (held[i])
                      v[i] = 0.;
                    else
                      v[i] += 0.5 * h * a[i];
                }
              time_spent.callback += seconds_since(start);
            }
          energy.record(record);
          record.energy_drift = conserved.drift();
          ++time_spent.n_steps;
          if (energy.unstable(settings.energy_tolerance))
            {
              time_spent.steps = seconds_since(loop_start);
              on_step(record);
              double local[3] = {0., 0., 0.};
              for (std::size_t i = 0; i < n; ++i)
                if (!held[i])
                  {
                    local[0] += half[i] * half_old[i];
                    local[1] += half[i] * half[i];
                    local[2] += half_old[i] * half_old[i];
                  }
              double global[3];
              dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local,
                                                                          3),
                                          comm,
                                          dealii::ArrayView<double>(global, 3));
              const double correlation =
                global[1] > 0. && global[2] > 0. ?
                  global[0] / std::sqrt(global[1] * global[2]) :
                  -1.;
              throw_unstable(energy,
                             dt,
                             estimate.critical_time_step,
                             std::min(settings.safety_factor, 0.9),
                             step,
                             t,
                             true,
                             correlation,
                             report);
            }
          on_step(record);
        }
      time_spent.steps = seconds_since(loop_start);
    }

    namespace
    {
      /// The `explicit` driver plugin: CentralDifference.
      class ExplicitRun : public TimeIntegrationRun<CentralDifference>
      {
      public:
        /// Forces only: the step and its stable size (a power iteration of
        /// M^-1 K by internal forces) need no tangent.
        bool
        needs_tangent() const override
        {
          return false;
        }

        void
        initialize(const Settings    &settings,
                   const std::string &file,
                   const int          dim) override
        {
          Interface::initialize(settings, file, dim);
          parameters.check_time_stepping(file, dim, true);
          if (parameters.mass == "consistent")
            throw InputError(file,
                             "Driver/Mass",
                             "the explicit driver needs a lumped mass (a "
                             "consistent mass would need a solve per step)",
                             "lumped (or Type = newmark for a consistent "
                             "mass)");
        }

        std::vector<std::string>
        notes() const override
        {
          if (parameters.time_step == 0. && parameters.safety_factor > 1.)
            return {"Driver/Time step safety factor = " +
                    number(parameters.safety_factor) +
                    " is above 1: the central difference is unstable"};
          return {};
        }



        std::string
        first_step_note(const DynamicRecord &record) const override
        {
          const auto        &e = integrator->stability();
          std::ostringstream s;
          s << " = " << record.time_step / e.critical_time_step
            << " x dt_crit; dt_crit = 2/omega_max = " << e.critical_time_step
            << " s (power iteration, " << e.iterations
            << " iterations, last change " << e.last_change << ")";
          return s.str();
        }

        void
        write_summary(IO::JsonWriter &json) const override
        {
          const auto  &e  = integrator->stability();
          const double dt = integrator->time_step();
          json.value("integrator", "central difference");
          json.value("time_step", dt);
          json.value("end_time", parameters.end_time);
          json.value("critical_time_step", e.critical_time_step);
          json.value("time_step_ratio",
                     e.critical_time_step > 0. ? dt / e.critical_time_step :
                                                 0.);
          json.value("omega_max", e.omega_max);
          json.value("eigenvalue_iterations",
                     static_cast<unsigned long>(e.iterations));
          json.value("eigenvalue_last_change", e.last_change);
          const auto &i = integrator->instability();
          if (i.unstable)
            {
              json.value("growth_per_step", i.growth_per_step);
              json.value("estimated_critical_time_step",
                         i.estimated_critical_step);
              json.value("time_step_reduction", i.recommended_factor);
              json.value("recommended_time_step", i.recommended_time_step);
            }
        }
      };
    } // namespace

    PDFEM_REGISTER_DRIVER(
      ExplicitRun,
      "explicit",
      "central difference with lumped mass in physical time t (specs/004 "
      "§2.3), automatic stable time step.")
  } // namespace Drivers
} // namespace pdfem
