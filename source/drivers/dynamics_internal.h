// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the dynamic drivers: the energy account and small helpers.
#ifndef PDFEM_SOURCE_DRIVERS_DYNAMICS_INTERNAL_H
#define PDFEM_SOURCE_DRIVERS_DYNAMICS_INTERNAL_H

#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/dynamics.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deque>
#include <vector>

#include "timing.h"

namespace pdfem
{
  namespace Drivers
  {
    namespace internal
    {
      using Vector = SystemInterface::Vector;

      /// 1 for each held owned-local DoF.
      inline std::vector<char>
      held_flags(const DynamicSystemInterface &system, const Vector &like)
      {
        std::vector<char> held(like.locally_owned_size(), 0);
        for (const unsigned int lid : system.held_dofs())
          held[lid] = 1;
        return held;
      }

      /// The energy balance of DynamicRecord, kept step by step.
      class EnergyAccount
      {
      public:
        /// Start with the state at t = 0 (f_int(u), f_ext(0)).
        void
        start(const Vector            &u,
              const Vector            &f_int,
              const Vector            &f_ext,
              const std::vector<char> &held,
              double                   kinetic,
              MPI_Comm                 comm);

        /**
         * A step from the displacement of the last call to @p u (the
         * forces at @p u given): external work by the trapezoidal rule,
         * strain energy. Returns nothing; see record().
         */
        void
        step(const Vector            &u,
             const Vector            &f_int,
             const Vector            &f_ext,
             const std::vector<char> &held,
             double                   kinetic);

        /// Bonds broke at fixed u: strain energy from @p before to the
        /// value for the new @p f_int is booked as dissipated.
        void
        bonds_broke(const Vector &u, const Vector &f_int);

        /// The model released @p energy of strain energy at fixed u without
        /// breaking bonds (its forces change from the next step on): it is
        /// booked as dissipated.
        void
        released(double energy);

        /// Fill the energy fields of @p r.
        void
        record(DynamicRecord &r) const;

        /// Relative error (see DynamicRecord).
        double
        error() const;

        /// Whether the error exceeds @p tolerance, did not decrease and the
        /// energy grew in each of the last three steps: an instability, not
        /// the start-up mismatch of a load that has supplied almost nothing
        /// yet (at step 1 of a ramp the work is 0 but v^1 = dt/2 a^1 is
        /// not, and the error then shrinks). Or, from step 4 on, whether
        /// the energy present exceeds 1e3 times the most ever supplied.
        bool
        unstable(double tolerance) const;

        /// Total energy (kinetic + strain + dissipated) history for the
        /// growth rate: energy ratio per step over the last steps.
        double
        growth_per_step() const;

        /// Put the account under @p prefix (checkpoint).
        void
        save(StateArchive &state, const std::string &prefix) const;
        /// Take it back; @p like gives the vectors' layout.
        void
        load(const StateArchive &state,
             const std::string  &prefix,
             const Vector       &like);

      private:
        MPI_Comm           comm = MPI_COMM_SELF;
        Vector             u_old, force_old;
        double             e0 = 0., work = 0., dissipated = 0.;
        double             kinetic = 0., strain = 0., peak = 0.;
        double             peak_total = 0.;
        std::deque<double> totals, errors;
        void
        applied_force(const Vector            &f_int,
                      const Vector            &f_ext,
                      const std::vector<char> &held,
                      Vector                  &force) const;
      };

      /**
       * The central difference's own conserved energy (the "shadow"
       * energy of the leapfrog scheme):
       *
       *   G^n = 1/2 v^(n+1/2) . M v^(n+1/2) + 1/2 u^n . f_int(u^(n+1)).
       *
       * For f_int = K u with K symmetric, the update M (v^(n+1/2) -
       * v^(n-1/2)) = dt (f_ext^n - K u^n) on the free DoFs gives exactly
       *
       *   G^n - G^(n-1) = F^n . (u^(n+1) - u^(n-1)) / 2,
       *
       * F = f_ext on free DoFs and f_int on held ones (the supports' work),
       * so that drift() = (G^n + dissipated - G^0 - work) / scale stays at
       * round-off however many steps run, while the energy of
       * EnergyAccount (kinetic energy at whole steps) oscillates by
       * O(dt^2). A non-symmetric K (the collocated pdlsm) makes it grow.
       * Bonds that break at u^(n+1) book 1/2 u^n . (f_int - f_int') as
       * dissipated. The scale is the largest |G^0 + work| or |G^n +
       * dissipated| so far.
       */
      class LeapfrogEnergy
      {
      public:
        /// The state at t = 0: u^0.
        void
        start(const Vector &u, MPI_Comm comm);

        /**
         * After step s of length dt: @p u = u^s, @p half = v^(s-1/2) (owned
         * entries), @p mass the lumped mass, f_int(u^s) and f_ext(t^s).
         * A step of another length (the shortened last one) leaves the
         * account as it is.
         */
        void
        step(const Vector              &u,
             const std::vector<double> &half,
             const Vector              &mass,
             const Vector              &f_int,
             const Vector              &f_ext,
             const std::vector<char>   &held);

        /// Bonds broke at the u^s of the last step(): f_int(u^s) is now
        /// @p f_int, and the held DoFs @p held.
        void
        bonds_broke(const Vector            &f_int,
                    const Vector            &f_ext,
                    const std::vector<char> &held);

        /// The model released @p energy at u^s without breaking bonds: it
        /// leaves the strain part and is booked as dissipated (to first
        /// order: the strain part is u^(s-1) . f(u^s) / 2, and the released
        /// energy is taken at u^s).
        void
        released(double energy);

        /// Relative drift of the conserved energy (0 before step 2).
        double
        drift() const;

        /// Put the account under @p prefix (checkpoint).
        void
        save(StateArchive &state, const std::string &prefix) const;
        /// Take it back; @p like gives the vectors' layout.
        void
        load(const StateArchive &state,
             const std::string  &prefix,
             const Vector       &like);

      private:
        MPI_Comm     comm    = MPI_COMM_SELF;
        unsigned int n_steps = 0;
        // u^(s-1), u^s and F^s after step s.
        Vector u_before, u_last, force_last;
        double g0 = 0., g = 0., work = 0., dissipated = 0., scale = 0.;
        /// 1/2 u^(s-1) . f_int(u^s) of the last step.
        double strain_part = 0.;
      };

      /**
       * What to report when the energy check fails: fills @p report and
       * throws RunFailure. An explicit step beyond the stability limit
       * excites a mode with u^n ~ lambda^n, lambda < -1: successive
       * half-step velocities are out of phase (@p correlation < 0), or dt
       * exceeds the power-iteration limit @p critical_step. Then the exit
       * state is "time step too large" with the factor to reduce dt by.
       * Otherwise (in-phase growth, or any growth under Newmark, which is
       * unconditionally stable) the semi-discrete system itself has growing
       * modes: exit state "unstable", and a smaller step would not help.
       */
      [[noreturn]] void
      throw_unstable(const EnergyAccount &energy,
                     double               dt,
                     double               critical_step,
                     double               safety,
                     unsigned int         step,
                     double               t,
                     bool                 explicit_scheme,
                     double               correlation,
                     InstabilityReport   &report);

      /**
       * What both time integrators carry from one step to the next
       * (checkpoints): the next step, v, a, the forces, the held DoFs and
       * the energy account, under "driver/".
       */
      struct TimeLoopState
      {
        Vector            &v, &a, &f_int, &f_ext;
        std::vector<char> &held;
        EnergyAccount     &energy;

        void
        save(StateArchive &state, unsigned int next_step) const;

        /// Take it back (@p u: the checkpoint's solution, for the layout);
        /// returns the next step. InputError if it does not fit the
        /// run's vectors.
        unsigned int
        load(const StateArchive &state, const Vector &u);
      };
    } // namespace internal
  }   // namespace Drivers
} // namespace pdfem

#endif
