// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_DYNAMICS_H
#define PDFEM_DRIVERS_DYNAMICS_H

#include <pdfem/drivers/dynamic_system_interface.h>

#include <functional>

namespace pdfem
{
  namespace Drivers
  {
    /**
     * What a time integrator reports after each step. Energies are per unit
     * thickness in 2D (multiply by DynamicSystemInterface::thickness()).
     *
     * Energy balance (free DoFs f, held DoFs p; specs/004 §2.3-2.4):
     *
     *   kinetic  = 1/2 v_f . M_ff v_f
     *   strain   = 1/2 u . f_int(u)
     *   external = sum over steps of 1/2 (F^n + F^n+1) . (u^n+1 - u^n),
     *              F = f_ext on free DoFs, f_int on held ones (the work of
     *              the loads and of the supports)
     *   dissipated = strain energy released by bonds that broke (the drop
     *              of 1/2 u . f_int at fixed u when the after-step callback
     *              breaks bonds)
     *   energy_error = (kinetic + strain + dissipated - external - E_0)
     *              / (largest |E_0 + external| so far).
     *
     * For a linear symmetric K, d/dt (kinetic + strain) = v_f . f_ext +
     * v_p . f_int,p exactly, so the error measures the integrator alone:
     * zero to round-off for average-acceleration Newmark, a bounded
     * O(dt^2) oscillation for a stable central difference, and exponential
     * growth when the step is too large.
     *
     *   energy_drift = the scheme's own conserved energy, relative: for the
     *              central difference the leapfrog energy G^n = 1/2
     *              v^(n+1/2) . M v^(n+1/2) + 1/2 u^n . f_int(u^(n+1)),
     *              whose balance with the work sum F^n . (u^(n+1) -
     *              u^(n-1)) / 2 holds exactly for a linear symmetric K (a
     *              round-off drift over any number of steps; growth with
     *              a non-symmetric K); for Newmark the energy_error (the
     *              trapezoidal rule's identity for beta = 1/4, gamma = 1/2;
     *              HHT-alpha and gamma > 1/2 dissipate).
     */
    struct DynamicRecord
    {
      unsigned int step              = 0;
      double       time              = 0.;
      double       time_step         = 0.;
      double       kinetic_energy    = 0.;
      double       strain_energy     = 0.;
      double       external_work     = 0.;
      double       dissipated_energy = 0.;
      double       energy_error      = 0.;
      double       energy_drift      = 0.;
      unsigned int linear_iterations = 0;
      unsigned int n_factorizations  = 0;
      bool         bonds_broke       = false;
    };

    /** Wall time per phase of a dynamic run. */
    struct DynamicTimings
    {
      double       internal_force = 0.; // f_int products
      double       external_force = 0.;
      double       update         = 0.; // vector updates, energies
      double       factorize      = 0.; // K_N assembly + factorisation
      double       solve          = 0.; // K_N solves
      double       callback       = 0.; // after-step hook (bond breaking)
      double       steps          = 0.; // the whole time loop
      double       eigenvalue     = 0.; // power iteration
      unsigned int n_steps        = 0;
    };

    /**
     * The stable time step of the central difference with lumped mass:
     * dt_crit = 2 / omega_max, omega_max^2 the largest eigenvalue of M^-1 K
     * over the free DoFs (Belytschko et al., Nonlinear FE, §6.3).
     */
    struct StabilityEstimate
    {
      double       lambda_max         = 0.; // omega_max^2 [1/s^2]
      double       omega_max          = 0.; // [1/s]
      double       critical_time_step = 0.; // 2 / omega_max [s]
      unsigned int iterations         = 0;
      /// Relative change of the estimate in the last iteration.
      double last_change = 0.;
    };

    /**
     * Largest eigenvalue of M^-1 K by @p iterations power iterations with
     * matrix-free products K x = f_int(x) (held DoFs removed). The estimate
     * is the larger of the Rayleigh quotient x.Kx / x.Mx and the M-norm
     * ratio |M^-1 K x|_M / |x|_M; for a symmetric K both approach
     * omega_max^2 from below, the quotient with twice the convergence rate.
     * The start vector is a fixed pseudo-random field of the global DoF
     * index (the same on any number of ranks).
     */
    StabilityEstimate
    estimate_stable_time_step(DynamicSystemInterface &system,
                              unsigned int            iterations);

    /**
     * Optional hook called after each step with the new displacement and
     * time: it may break bonds (a fracture criterion) and returns whether
     * any broke. The integrator then books the released strain energy as
     * dissipated and recomputes the forces (Newmark: refactorises K_N).
     */
    using AfterStep =
      std::function<bool(const SystemInterface::Vector &u, double t)>;
    using OnStep = std::function<void(const DynamicRecord &)>;

    /**
     * Solution changes integrators recommend when a run became unstable:
     * filled when they throw RunFailure("time step too large").
     */
    struct InstabilityReport
    {
      bool   unstable                = false;
      double growth_per_step         = 0.; // energy ratio per step
      double estimated_critical_step = 0.; // from the growth rate
      double recommended_factor      = 1.; // multiply dt by at most this
      double recommended_time_step   = 0.;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
