// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_STATIC_DRIVER_H
#define PDFEM_DRIVERS_STATIC_DRIVER_H

#include <pdfem/drivers/resume.h>
#include <pdfem/drivers/settings.h>
#include <pdfem/drivers/system_interface.h>

#include <functional>

namespace pdfem
{
  namespace Drivers
  {
    /** What a driver reports after each converged step. */
    struct StepRecord
    {
      unsigned int step              = 0;
      double       time              = 0.;
      double       load_factor       = 0.;
      unsigned int newton_iterations = 0;
      unsigned int linear_iterations = 0;
      /// |r| / max(|r_0|, |f_ext|, |f_int|) at convergence.
      double relative_residual = 0.;
    };

    /** Wall time a driver spent per phase. */
    struct DriverTimings
    {
      double assembly = 0.;
      double solve    = 0.;
    };

    /**
     * Equilibrium at load factor @p t: predict, set the prescribed DoFs,
     * then Newton iterations K du = r, u += du until
     * |r| <= tol * max(|r_0|, |f_ext|, |f_int|) (see StaticDriver). Throws
     * RunFailure("diverged") after `Max iterations`. @p step only labels
     * the record and messages.
     *
     * The predictor: if @p u is the equilibrium at load factor
     * @p t_of_u > 0, it is scaled by t / t_of_u. For the linear coupled
     * problem with loads proportional to t (the drivers' assumption) that
     * is the new equilibrium to rounding, which the first residual accepts
     * without a linear solve; otherwise it is a first guess for Newton.
     * Pass 0 for no prediction.
     */
    StepRecord
    equilibrate(SystemInterface         &system,
                SystemInterface::Vector &u,
                double                   t,
                double                   t_of_u,
                unsigned int             step,
                const Settings          &settings,
                DriverTimings           &time_spent);

    /**
     * The load steps of a static driver: t = k / @p n_steps for k from 1
     * (or from the step @p resume restarts at), a checkpoint boundary
     * before every step but the first one run, and
     * @p on_step(@p solve(t, t_previous, k)) for each.
     */
    void
    run_load_steps(
      unsigned int                                                   n_steps,
      const Resume                                                  &resume,
      const std::function<StepRecord(double, double, unsigned int)> &solve,
      const std::function<void(const StepRecord &)>                 &on_step);

    /**
     * Static equilibrium: the load factor t goes from 0 to 1 in `Load steps`
     * equal increments; at each, the prescribed DoFs are set to their values
     * at t and Newton iterations K du = r, u += du run until
     * |r| <= tol * max(|r_0|, |f_ext|, |f_int|); |f_int| includes the
     * reactions, the force scale of displacement-driven problems (a step
     * that starts in equilibrium has |r_0| and |f_ext| at round-off). For
     * the linear coupled PDLSM-FE
     * problem one iteration is exact; the second residual only confirms it.
     * No convergence in `Max iterations` throws RunFailure("diverged").
     */
    class StaticDriver
    {
    public:
      explicit StaticDriver(const Settings &settings);

      /// @p u: initial guess in, solution out. @p on_step is called after
      /// each converged step (before the next one changes anything).
      void
      run(SystemInterface                               &system,
          SystemInterface::Vector                       &u,
          const std::function<void(const StepRecord &)> &on_step,
          const Resume                                  &resume = {});

      const DriverTimings &
      timings() const
      {
        return time_spent;
      }

    private:
      Settings      settings;
      DriverTimings time_spent;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
