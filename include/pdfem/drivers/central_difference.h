// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_CENTRAL_DIFFERENCE_H
#define PDFEM_DRIVERS_CENTRAL_DIFFERENCE_H

#include <pdfem/drivers/dynamics.h>
#include <pdfem/drivers/resume.h>
#include <pdfem/drivers/settings.h>

namespace pdfem
{
  namespace Drivers
  {
    /**
     * Explicit central difference with lumped mass (specs/004 §2.3, eq. 34
     * of Liu & Xin), written in the equivalent velocity-Verlet form
     * (Belytschko et al., Box 6.1):
     *
     *   v^n+1/2 = v^n + dt/2 a^n
     *   u^n+1   = u^n + dt v^n+1/2      (prescribed DoFs: u_p(t^n+1))
     *   a^n+1   = M^-1 (f_ext(t^n+1) - f_int(u^n+1))
     *   v^n+1   = v^n+1/2 + dt/2 a^n+1
     *
     * with f_int matrix-free and no global matrix. The step is
     * 'Time step safety factor' x 2/omega_max (estimate_stable_time_step)
     * unless 'Time step' is given. The energy balance (DynamicRecord) is
     * evaluated every step; when the energy exceeds what was supplied by
     * more than 'Energy tolerance' the run stops with RunFailure("time step
     * too large"), the message giving the factor by which to reduce dt,
     * from the measured growth rate: an unstable mode grows by |lambda|^2
     * in energy per step with sqrt|lambda| + 1/sqrt|lambda| = omega dt, so
     * dt_crit = dt / ((sqrt|lambda| + 1/sqrt|lambda|) / 2).
     */
    class CentralDifference
    {
    public:
      explicit CentralDifference(const Settings &settings);

      /**
       * Integrate from t = 0 (u = @p u with the prescribed values at t = 0,
       * v = @p v0 on the free DoFs) to the end time. @p on_step is called
       * after step 0 and every step; @p after_step (if given) after every
       * step, before on_step. With @p resume, it goes on from a
       * checkpoint's state (time step and estimate kept, no power
       * iteration) and offers its state between steps.
       */
      void
      run(DynamicSystemInterface        &system,
          SystemInterface::Vector       &u,
          const SystemInterface::Vector &v0,
          const OnStep                  &on_step,
          const AfterStep               &after_step = {},
          const Resume                  &resume     = {});

      /// The step used (after run() started).
      double
      time_step() const
      {
        return dt;
      }
      const StabilityEstimate &
      stability() const
      {
        return estimate;
      }
      const DynamicTimings &
      timings() const
      {
        return time_spent;
      }
      const InstabilityReport &
      instability() const
      {
        return report;
      }

    private:
      /// dt from the settings and the estimate; refuses a given step above
      /// the critical one (RunFailure "time step too large").
      void
      check_time_step();

      Settings          settings;
      double            dt = 0.;
      StabilityEstimate estimate;
      DynamicTimings    time_spent;
      InstabilityReport report;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
