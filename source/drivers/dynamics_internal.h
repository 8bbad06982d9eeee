// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the dynamic drivers: the energy account and small helpers.
#ifndef PDFEM_SOURCE_DRIVERS_DYNAMICS_INTERNAL_H
#define PDFEM_SOURCE_DRIVERS_DYNAMICS_INTERNAL_H

#include <pdfem/drivers/dynamics.h>

#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <deque>
#include <vector>

namespace pdfem
{
  namespace Drivers
  {
    namespace internal
    {
      using Vector = SystemInterface::Vector;
      using clock  = std::chrono::steady_clock;

      inline double
      seconds_since(const clock::time_point &start)
      {
        return std::chrono::duration<double>(clock::now() - start).count();
      }

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
        /// not, and the error then shrinks).
        bool
        unstable(double tolerance) const;

        /// Total energy (kinetic + strain + dissipated) history for the
        /// growth rate: energy ratio per step over the last steps.
        double
        growth_per_step() const;

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
    } // namespace internal
  }   // namespace Drivers
} // namespace pdfem

#endif
