// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_NEWMARK_H
#define PDFEM_DRIVERS_NEWMARK_H

#include <pdfem/drivers/dynamics.h>
#include <pdfem/drivers/resume.h>
#include <pdfem/drivers/settings.h>

namespace pdfem
{
  namespace Drivers
  {
    /**
     * Implicit Newmark (beta, gamma) in acceleration form (specs/004 §2.4;
     * Liu & Xin eqs. 36-40):
     *
     *   predictor  u~ = u^n + dt v^n + dt^2 (1/2 - beta) a^n
     *              (prescribed DoFs: u_p(t^n+1))
     *   solve      K_N a^n+1 = f_ext(t^n+1) - f_int(u~),
     *              K_N = M + beta dt^2 K
     *   correct    u^n+1 = u~ + beta dt^2 a^n+1
     *              v^n+1 = v^n + dt ((1 - gamma) a^n + gamma a^n+1)
     *
     * M lumped or consistent (FE consistent + PD rho V). K is constant
     * while no bond breaks (the PDLSM-FE operator is linear), so K_N is
     * assembled and factorised once and reused; an after-step callback that
     * breaks bonds triggers a new factorisation ('Reuse factorization =
     * false' refactorises every step, like the peer code). Average
     * acceleration (beta = 1/4, gamma = 1/2) conserves kinetic + strain
     * energy exactly for a symmetric K; a0 solves M a0 = f_ext - f_int.
     */
    class Newmark
    {
    public:
      explicit Newmark(const Settings &settings);

      /**
       * As CentralDifference::run(), with @p resume going on from a
       * checkpoint's state (v, a, the forces, the held DoFs, the HHT
       * residual, the energy account): K_N is factorised again there, which
       * n_factorizations() does not count (the run left alone reuses the
       * factorisation it had).
       */
      void
      run(DynamicSystemInterface        &system,
          SystemInterface::Vector       &u,
          const SystemInterface::Vector &v0,
          const OnStep                  &on_step,
          const AfterStep               &after_step = {},
          const Resume                  &resume     = {});

      double
      time_step() const
      {
        return settings.time_step;
      }
      const DynamicTimings &
      timings() const
      {
        return time_spent;
      }
      unsigned int
      n_factorizations() const
      {
        return factorizations;
      }

    private:
      Settings       settings;
      DynamicTimings time_spent;
      unsigned int   factorizations = 0;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
