// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/drivers/newmark.h>

#include <deal.II/base/mpi.h>

#include <cmath>

#include "dynamics_internal.h"
#include "time_integration_run.h"

namespace pdfem
{
  namespace Drivers
  {
    using namespace internal;

    Newmark::Newmark(const Settings &settings)
      : settings(settings)
    {}

    void
    Newmark::run(DynamicSystemInterface &system,
                 Vector                 &U,
                 const Vector           &v0,
                 const OnStep           &on_step,
                 const AfterStep        &after_step,
                 const Resume           &resume)
    {
      const double dt = settings.time_step;
      // HHT-alpha (Hilber, Hughes & Taylor 1977): alpha in [-1/3, 0] damps
      // high frequencies; beta and gamma follow from it.
      const double alpha = settings.hht_alpha;
      const double beta =
        alpha != 0. ? (1. - alpha) * (1. - alpha) / 4. : settings.newmark_beta;
      const double gamma = alpha != 0. ? 0.5 - alpha : settings.newmark_gamma;
      const bool   consistent = settings.mass == "consistent";
      const unsigned int n_steps =
        static_cast<unsigned int>(std::ceil(settings.end_time / dt - 1e-9));
      const MPI_Comm comm = U.get_mpi_communicator();

      const Vector &M = system.lumped_mass();
      // R_old = f_ext - f_int at the last step (HHT's alpha-weighted part).
      Vector V, A, A_new, F_int, F_ext, R, R_old, MV;
      for (Vector *w : {&V, &A, &A_new, &F_int, &F_ext, &R, &R_old, &MV})
        system.initialize_vector(*w);
      std::vector<char> held = held_flags(system, U);
      const std::size_t n    = held.size();

      auto kinetic = [&]() {
        // 1/2 v_f . M_ff v_f: held entries of v are zero.
        system.mass_vmult(MV, V);
        return 0.5 * (V * MV);
      };
      auto zero_held = [&](Vector &w) {
        double *x = w.begin();
        for (std::size_t i = 0; i < n; ++i)
          if (held[i])
            x[i] = 0.;
      };
      auto factorize = [&]() {
        const auto start = clock::now();
        system.factorize_effective(1.,
                                   (1. + alpha) * beta * dt * dt,
                                   consistent);
        ++factorizations;
        time_spent.factorize += seconds_since(start);
      };

      EnergyAccount energy;
      DynamicRecord record;
      unsigned int  first = 1;
      // K_N is factorised before the next step.
      bool          refactor = true;
      TimeLoopState loop{V, A, F_int, F_ext, held, energy};
      if (resume.from)
        {
          // Everything the loop carries from one step to the next, as it
          // was at the checkpoint.
          const StateArchive &state = *resume.from;
          first                     = loop.load(state, U);
          factorizations = state.get<unsigned int>("driver/factorizations");
          state.get_owned("driver/r_old", R_old);
          // The run left alone reuses its factorisation here unless bonds
          // broke in the last step: a restart's first one replaces it and
          // is not counted.
          if (!state.get<bool>("driver/refactor") &&
              settings.reuse_factorization)
            --factorizations;
        }
      else
        {
          // t = 0: a0 from M a0 = f_ext - f_int on the free DoFs.
          system.apply_dirichlet(U, 0.);
          V = v0;
          zero_held(V);
          system.internal_force(U, F_int);
          system.external_force(0., F_ext);
          R = F_ext;
          R -= F_int;
          zero_held(R);
          R_old = R;
          if (consistent)
            {
              auto start = clock::now();
              system.factorize_effective(1., 0., true);
              ++factorizations;
              time_spent.factorize += seconds_since(start);
              start = clock::now();
              system.solve_effective(A, R);
              time_spent.solve += seconds_since(start);
            }
          else
            {
              A               = R;
              const double *m = M.begin();
              double       *a = A.begin();
              for (std::size_t i = 0; i < n; ++i)
                a[i] = held[i] ? 0. : a[i] / m[i];
            }
          energy.start(U, F_int, F_ext, held, kinetic(), comm);
          record.time_step = dt;
          energy.record(record);
          on_step(record);
        }
      const auto save = [&](StateArchive &state, const unsigned int step) {
        loop.save(state, step);
        state.put("driver/factorizations", factorizations);
        state.put_owned("driver/r_old", R_old);
        state.put("driver/refactor", refactor);
      };

      const auto loop_start = clock::now();
      for (unsigned int step = first; step <= n_steps; ++step)
        {
          if (step > first && resume.boundary)
            resume.boundary([&](StateArchive &state) { save(state, step); });
          const double t = step * dt;
          if (refactor || !settings.reuse_factorization)
            {
              factorize();
              refactor = false;
            }
          // Predictor u~ (in U) on the free DoFs; held DoFs (v = a = 0
          // there) keep their value or take the prescribed one at t.
          auto start = clock::now();
          {
            double       *u = U.begin();
            const double *v = V.begin();
            const double *a = A.begin();
            for (std::size_t i = 0; i < n; ++i)
              if (!held[i])
                u[i] += dt * v[i] + dt * dt * (0.5 - beta) * a[i];
          }
          system.apply_dirichlet(U, t);
          time_spent.update += seconds_since(start);

          start = clock::now();
          system.internal_force(U, F_int);
          time_spent.internal_force += seconds_since(start);
          start = clock::now();
          system.external_force(t, F_ext);
          time_spent.external_force += seconds_since(start);
          // (1 + alpha)(f_ext^n+1 - f_int(u~)) - alpha (f_ext^n - f_int(u^n))
          R = F_ext;
          R -= F_int;
          zero_held(R);
          if (alpha != 0.)
            {
              R *= 1. + alpha;
              R.add(-alpha, R_old);
            }

          start                    = clock::now();
          record                   = DynamicRecord();
          record.linear_iterations = system.solve_effective(A_new, R);
          time_spent.solve += seconds_since(start);

          start = clock::now();
          {
            double      *u    = U.begin();
            double      *v    = V.begin();
            double      *a    = A.begin();
            double      *an   = A_new.begin();
            const double bdt2 = beta * dt * dt;
            for (std::size_t i = 0; i < n; ++i)
              if (!held[i])
                {
                  u[i] += bdt2 * an[i];
                  v[i] += dt * ((1. - gamma) * a[i] + gamma * an[i]);
                  a[i] = an[i];
                }
          }
          time_spent.update += seconds_since(start);
          start = clock::now();
          system.internal_force(U, F_int);
          time_spent.internal_force += seconds_since(start);
          start = clock::now();
          energy.step(U, F_int, F_ext, held, kinetic());
          if (alpha != 0.)
            {
              R_old = F_ext;
              R_old -= F_int;
              zero_held(R_old);
            }
          time_spent.update += seconds_since(start);

          record.step             = step;
          record.time             = t;
          record.time_step        = dt;
          record.n_factorizations = factorizations;
          if (after_step)
            {
              start              = clock::now();
              record.bonds_broke = after_step(U, t);
              if (record.bonds_broke)
                {
                  held = held_flags(system, U);
                  zero_held(V);
                  zero_held(A);
                  system.internal_force(U, F_int);
                  energy.bonds_broke(U, F_int);
                  // a^n+1 for the new bonds (M a = f_ext - f_int(u)), so
                  // that the next step starts in balance; K_N is
                  // refactorised at the next step.
                  R = F_ext;
                  R -= F_int;
                  zero_held(R);
                  R_old = R;
                  if (consistent)
                    {
                      const auto t0 = clock::now();
                      system.factorize_effective(1., 0., true);
                      ++factorizations;
                      system.solve_effective(A, R);
                      time_spent.factorize += seconds_since(t0);
                    }
                  else
                    {
                      const double *m = M.begin();
                      const double *r = R.begin();
                      double       *a = A.begin();
                      for (std::size_t i = 0; i < n; ++i)
                        a[i] = held[i] ? 0. : r[i] / m[i];
                    }
                  refactor = true;
                }
              time_spent.callback += seconds_since(start);
            }
          energy.record(record);
          // The trapezoidal rule's account is the scheme's own identity.
          record.energy_drift = record.energy_error;
          ++time_spent.n_steps;
          if (energy.unstable(settings.energy_tolerance))
            {
              time_spent.steps = seconds_since(loop_start);
              on_step(record);
              InstabilityReport report;
              throw_unstable(energy, dt, 0., 0.9, step, t, false, 1., report);
            }
          on_step(record);
        }
      time_spent.steps = seconds_since(loop_start);
    }

    namespace
    {
      /// The `newmark` driver plugin: Newmark (HHT-alpha).
      class NewmarkRun : public TimeIntegrationRun<Newmark>
      {
      public:
        void
        initialize(const Settings    &settings,
                   const std::string &file,
                   const int          dim) override
        {
          Interface::initialize(settings, file, dim);
          parameters.check_time_stepping(file, dim, false);
          const std::string p     = "Driver/";
          const double      gamma = parameters.newmark_gamma,
                       beta       = parameters.newmark_beta;
          if (parameters.time_step == 0.)
            throw InputError(file,
                             p + "Time step",
                             "'auto' is for the explicit driver only "
                             "(Newmark is unconditionally stable: the step "
                             "is an accuracy choice)",
                             "dt > 0 [s]");
          // The run ends at the end time exactly: a step that does not
          // divide it is shortened to the next one that does (one
          // factorisation for every step).
          const double n_steps =
            std::ceil(parameters.end_time / parameters.time_step - 1e-9);
          if (std::abs(n_steps * parameters.time_step - parameters.end_time) >
              1e-9 * parameters.end_time)
            {
              const double given   = parameters.time_step;
              parameters.time_step = parameters.end_time / n_steps;
              step_note = p + "Time step " + number(given) + " s does not " +
                          "divide End time " + number(parameters.end_time) +
                          " s: " + number(n_steps) + " steps of " +
                          number(parameters.time_step) + " s";
            }
          if (parameters.hht_alpha != 0.)
            return; // HHT sets beta and gamma
          if (!(gamma >= 0.5))
            throw InputError(file,
                             p + "Newmark gamma",
                             "gamma = " + number(gamma) +
                               " is outside the stable range (gamma < 1/2 "
                               "amplifies every mode)",
                             "gamma >= 0.5 with beta >= (2 gamma + 1)^2 / 16");
          const double beta_min = (2. * gamma + 1.) * (2. * gamma + 1.) / 16.;
          if (!(beta >= beta_min - 1e-14) || !(beta <= 1.))
            throw InputError(file,
                             p + "Newmark beta",
                             "beta = " + number(beta) +
                               " is outside the unconditionally stable range "
                               "for gamma = " +
                               number(gamma),
                             number(beta_min) +
                               " = (2 gamma + 1)^2 / 16 <= beta <= 1");
        }

        std::vector<std::string>
        notes() const override
        {
          if (step_note.empty())
            return {};
          return {step_note};
        }

        bool
        needs_assembled_matrix() const override
        {
          return true;
        }

        void
        check(const RunTraits &traits) const override
        {
          TimeIntegrationRun<Newmark>::check(traits);
          if (!traits.assembled_matrix)
            throw InputError(traits.file,
                             "Linear solver/Preconditioner",
                             "'amg fe' has no assembled matrix, which Newmark "
                             "factorises once and reuses",
                             "amg or ilu (or Type = direct)");
        }



        void
        write_summary(IO::JsonWriter &json) const override
        {
          json.value("integrator", "newmark");
          json.value("time_step", parameters.time_step);
          json.value("end_time", parameters.end_time);
          json.value("newmark_beta", parameters.newmark_beta);
          json.value("newmark_gamma", parameters.newmark_gamma);
          json.value("factorizations",
                     static_cast<unsigned long>(
                       integrator ? integrator->n_factorizations() : 0));
        }

      private:
        /// Why the time step was shortened (empty: it was not).
        std::string step_note;
      };
    } // namespace

    PDFEM_REGISTER_DRIVER(
      NewmarkRun,
      "newmark",
      "implicit Newmark (beta, gamma; HHT-alpha) in physical time t (specs/004 "
      "§2.4), the factorisation of M + beta dt^2 K reused while no bond "
      "breaks.")
  } // namespace Drivers
} // namespace pdfem
