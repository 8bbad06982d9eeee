// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_DYNAMIC_RELAXATION_H
#define PDFEM_DRIVERS_DYNAMIC_RELAXATION_H

#include <pdfem/drivers/progress_pulse.h>
#include <pdfem/drivers/resume.h>
#include <pdfem/drivers/settings.h>
#include <pdfem/drivers/static_driver.h>
#include <pdfem/drivers/system_interface.h>

#include <functional>
#include <string>

namespace pdfem
{
  namespace Drivers
  {
    struct RunTraits;

    /// InputError (naming @p file) for a `Dynamic relaxation` damping or
    /// density factor that cannot work.
    void
    check_relaxation_settings(const Settings    &settings,
                              const std::string &file);

    /// InputError where the run builds no assembled tangent (the density's
    /// bound needs it).
    void
    check_relaxation_traits(const RunTraits &traits);

    /**
     * Adaptive dynamic relaxation (Kilic & Madenci 2010; specs/003 §2):
     * static equilibrium r(u) = f_ext - f_int(u) = 0 as the steady state of
     * the damped pseudo-dynamics Lambda u'' + c Lambda u' = r(u) with the
     * step dt = 1,
     *
     *   v^{n+1/2} = ((2 - c^n) v^{n-1/2} + 2 Lambda^-1 r(u^n)) / (2 + c^n),
     *   u^{n+1}   = u^n + v^{n+1/2},   v^{1/2} = Lambda^-1 r(u^0) / 2,
     *
     * the diagonal fictitious density Lambda_ii = f / 4 sum_j |K_ij| (the
     * Gershgorin bound of the tangent at the start of each load step, f
     * `Density factor`: central differences are then stable for a linear
     * model) and the damping c^n = 2 sqrt(u^T K_local u / u^T u) from the
     * local stiffness K_local,ii = -(r_i^n - r_i^{n-1}) / (Lambda_ii
     * v_i^{n-1/2}) (0 if the quotient is not positive, 1.9 if it exceeds
     * 2), or a fixed c. Only forces are evaluated: any PD model that gives
     * them (and a tangent for the bound) works.
     *
     * The load factor goes from 0 to 1 in `Load steps` increments as in
     * StaticDriver, each over `Ramp iterations` iterations (the prescribed
     * displacements move at a finite rate; 0: at once, after scaling u by
     * the load ratio), and is relaxed until |r| <= tol max(|r_0|, |f_ext|,
     * |f_int|), the static drivers' test, so that a relaxed state and a
     * Newton state of the same step agree to the tolerance. A model's
     * history follows the accepted states only (one per load step), as
     * with Newton; the paper's "one boundary increment per iteration" is
     * Load steps = the number of iterations it ramps over (specs/003 §2,
     * [AMB] (b)).
     */
    class DynamicRelaxation
    {
    public:
      explicit DynamicRelaxation(const Settings &settings);

      /// Relax @p u to equilibrium at load factor @p t (the prescribed DoFs
      /// set to their values at t); @p t_of_u > 0: @p u is the equilibrium
      /// at that load factor and is scaled by t / t_of_u first. The
      /// record's newton_iterations are the relaxation iterations.
      StepRecord
      relax(SystemInterface         &system,
            SystemInterface::Vector &u,
            double                   t,
            double                   t_of_u,
            unsigned int             step);

      /// All load steps; @p on_step after each relaxed one.
      void
      run(SystemInterface                               &system,
          SystemInterface::Vector                       &u,
          const std::function<void(const StepRecord &)> &on_step,
          const Resume                                  &resume = {});

      /// "assembly": residuals and the density's tangent; "solve": the
      /// vector updates.
      const DriverTimings &
      timings() const
      {
        return time_spent;
      }

      /// Relaxation iterations over all steps so far.
      unsigned long
      iterations() const
      {
        return total_iterations;
      }

      /// Lines from inside a load step (relaxation iterations) through
      /// @p pulse.
      void
      set_progress(const ProgressPulse &pulse)
      {
        progress = pulse;
      }

      /// A restarted run: count on from @p n iterations (a checkpoint's).
      void
      resume_iterations(const unsigned long n)
      {
        total_iterations = n;
      }

    private:
      Settings      settings;
      double        fixed_damping = -1.; // < 0: adaptive
      DriverTimings time_spent;
      unsigned long total_iterations = 0;
      ProgressPulse progress;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
