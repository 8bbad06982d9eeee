// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_QUASI_STATIC_DRIVER_H
#define PDFEM_DRIVERS_QUASI_STATIC_DRIVER_H

#include <pdfem/drivers/settings.h>
#include <pdfem/drivers/static_driver.h>
#include <pdfem/drivers/system_interface.h>

#include <functional>
#include <limits>
#include <string>

namespace pdfem
{
  namespace Drivers
  {
    /** What the crack criterion did after one equilibrium. */
    struct GrowthCheck
    {
      /// Did a crack grow (bonds break)? Then the load is held.
      bool grew = false;
      /// Critical over current load (loads proportional to t).
      double critical_load_ratio = std::numeric_limits<double>::infinity();
      /// Is the body cut through? The run ends (exit state "separated").
      bool separated = false;
      /// How the separation was found, for the message (empty: no piece
      /// of the body links the grips any more).
      std::string separation;
    };

    /**
     * Quasi-static crack growth (specs/004 §2.2, P Fig. 5), for any
     * criterion: at each step, equilibrium at load factor t (from the last
     * solution scaled to t: see equilibrate()), then the criterion. Where a
     * crack grew, t is held and the next step finds the new equilibrium with
     * the longer crack; otherwise t grows by the nominal increment dt, or, with
     * `Jump to critical load`, by (r - 1) t with r = 1.001 x critical load
     * ratio when that is smaller (the load extrapolated linearly to where the
     * criterion is met: PDLSM-FEM's rule). The run ends after `Load steps`
     * steps, or when the body is cut through (RunFailure "separated").
     */
    class QuasiStaticDriver
    {
    public:
      explicit QuasiStaticDriver(const Settings &settings);

      /**
       * @p system returns the current system (a criterion may rebuild it
       * with a larger PD region; the DoF layout stays). @p after_step
       * receives each equilibrium and runs the criterion.
       */
      void
      run(const std::function<SystemInterface &()>             &system,
          SystemInterface::Vector                              &u,
          const std::function<GrowthCheck(const StepRecord &)> &after_step,
          const Resume                                         &resume = {});

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
