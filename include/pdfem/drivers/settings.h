// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_SETTINGS_H
#define PDFEM_DRIVERS_SETTINGS_H

#include <array>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace pdfem
{
  namespace Drivers
  {
    /** A node whose displacement history.csv records every step. */
    struct MonitorPoint
    {
      std::string           name;
      std::array<double, 3> point = {{0., 0., 0.}};
    };

    /**
     * `subsection Driver`: static equilibrium, or a dynamic run (explicit
     * central difference or Newmark) in physical time t.
     */
    struct Settings
    {
      /// static | quasi-static | newton | arc length | explicit | newmark
      std::string  type       = "static";
      unsigned int load_steps = 1;
      /// quasi-static: the nominal increment of t (0: 1 / Load steps).
      double load_increment = 0.;
      /// quasi-static: the first solve is at this t (PDLSM-FEM: 0).
      double initial_load = -1.; // < 0: one increment (Initial load)
      /// quasi-static: jump to the extrapolated critical load when it is
      /// nearer than the nominal increment (PDLSM-FEM's rule).
      bool jump_to_critical_load = true;
      /// quasi-static: keep t while cracks grow (PDLSM-FEM); if false, t
      /// follows its schedule whatever breaks (load histories).
      bool         hold_load_while_growing = true;
      double       residual_tolerance = 1e-9; // relative to |f_ext| (or |r_0|)
      unsigned int max_iterations     = 10;
      // newton only: load step cutting, line search, stability check
      unsigned int max_step_cuts    = 4;
      double       step_cut_factor  = 0.25;
      bool         line_search      = true;
      bool         stability_check  = true;
      unsigned int arc_length_steps = 50; // arc length only

      /// @name Dynamic runs (Type = explicit or newmark)
      /// @{
      /// Time step [s]; 0 = automatic (explicit only): safety factor times
      /// the critical step 2 / omega_max.
      double time_step = 0.;
      /// End time [s] (> 0 for a dynamic run).
      double end_time = 0.;
      /// Explicit: the automatic step is this times 2 / omega_max.
      double safety_factor = 0.9;
      /// Power iterations for the largest eigenvalue of M^-1 K.
      unsigned int eigenvalue_iterations = 50;
      /// Newmark parameters (average acceleration by default).
      double newmark_beta  = 0.25;
      double newmark_gamma = 0.5;
      /// HHT-alpha in [-1/3, 0] (0: plain Newmark); if not 0, beta =
      /// (1 - alpha)^2 / 4 and gamma = 1/2 - alpha.
      double hht_alpha = 0.;
      /// lumped | consistent (consistent: Newmark only).
      std::string mass = "lumped";
      /// Newmark: reuse the factorisation of K_N while no bond breaks.
      bool reuse_factorization = true;
      /// Initial velocity: dim expressions of x, y, z (empty: at rest).
      std::vector<std::string> initial_velocity;
      /// The run stops ('time step too large') when the energy exceeds the
      /// energy supplied by more than this fraction of the peak supplied.
      double energy_tolerance = 0.5;
      /// Write a history row every this many steps (and the last one).
      unsigned int history_interval = 1;
      /// Nodes whose displacement is written to history.csv.
      std::vector<MonitorPoint> monitor_points;
      /// @}

      /// @name Dynamic relaxation (subsection Driver/Dynamic relaxation)
      /// @{
      /// The fictitious density is this times the Gershgorin bound
      /// 1/4 sum_j |K_ij| of the tangent (>= 1: stable for a linear model).
      double relaxation_density_factor = 1.;
      /// "adaptive" (the local Rayleigh quotient) or a fixed damping
      /// coefficient in [0, 2).
      std::string relaxation_damping = "adaptive";
      /// Relaxation iterations per load step before the run stops with
      /// exit state 'diverged'.
      unsigned int relaxation_max_iterations = 100000;
      /// The load of a step goes from the previous step's to its own over
      /// this many iterations (the boundary moves at a finite rate; 0: at
      /// once).
      unsigned int relaxation_ramp_iterations = 0;
      /// @}

      /// @name The adaptive explicit-implicit driver (Driver/Adaptive)
      /// @{
      /// N_i: the implicit load increment is 1 / N_i.
      unsigned int adaptive_implicit_steps = 5;
      /// N_e: the explicit increment is (1 - t_n) / N_e, t_n the load of
      /// the first switch to explicit.
      unsigned int adaptive_explicit_steps = 100;
      /// "onset" (a bond passes the threshold, or Newton fails) or
      /// "newton failure" (only the latter).
      std::string adaptive_to_explicit = "onset";
      /// "discard" (relax from the state before the onset step) or "keep"
      /// (from the onset step's Newton state, the paper's).
      std::string adaptive_onset_state = "discard";
      /// The threshold stretch as a fraction of s_m.
      double adaptive_onset_fraction = 1.;
      /// "quiet" (the damage stops growing) or "never".
      std::string adaptive_to_implicit = "quiet";
      /// The quiet window and the damage tolerance as given ("": unset;
      /// the quiet rule needs both, checked by the driver).
      std::string adaptive_quiet_steps_text;
      std::string adaptive_damage_tolerance_text;
      /// @}
      /// The texts of 'Time step' and 'Monitor points' as given (parsed
      /// by check_time_stepping()).
      std::string time_step_text;
      std::string monitor_points_text;

      /**
       * Validate the time-stepping entries (time step, end time, safety
       * factor, HHT alpha, initial velocity, energy tolerance, monitor
       * points) for a dynamic driver; @p automatic_step: 'auto' is allowed.
       */
      void
      check_time_stepping(const std::string &file,
                          int                dim,
                          bool               automatic_step);

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm, const std::string &file, int dim);
    };

  } // namespace Drivers
} // namespace pdfem

#endif
