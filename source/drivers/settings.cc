// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/drivers/settings.h>

#include <deal.II/base/parameter_handler.h>


namespace pdfem
{
  namespace Drivers
  {
    using dealii::ParameterHandler;
    using dealii::Patterns::Anything;
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    using namespace ParameterTools;

    // ---------------------------------------------------------------- Driver
    void
    Settings::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Driver");
      prm.declare_entry("Type",
                        "static",
                        Selection(registry().selection()),
                        "The driver (pdfem --list-plugins). " +
                          registry().summary() +
                          "In dynamic runs, t in the boundary expressions is "
                          "physical time.");
      prm.declare_entry("Load steps",
                        "1",
                        Integer(1),
                        "Number of load increments (static: t = k / Load "
                        "steps), or of steps in all (quasi-static).");
      prm.declare_entry("Load increment",
                        "0",
                        Double(0.),
                        "quasi-static: the nominal increment of t (0: 1 / "
                        "Load steps). Prescribed displacements and loads are "
                        "expressions of t.");
      prm.declare_entry("Initial load",
                        "-1",
                        Double(),
                        "quasi-static: the load factor t of the first "
                        "solve; < 0: one Load increment (PDLSM-FEM: 0, an "
                        "unloaded first step).");
      prm.declare_entry("Jump to critical load",
                        "true",
                        Bool(),
                        "quasi-static: when the load at which the criterion "
                        "would be met, extrapolated linearly from the last "
                        "step (loads proportional to t), is nearer than one "
                        "increment, go there directly (PDLSM-FEM's rule).");
      prm.declare_entry("Hold load while cracks grow",
                        "true",
                        Bool(),
                        "quasi-static: keep t where it is while the "
                        "criterion breaks bonds, until the cracks arrest "
                        "(PDLSM-FEM). false: t follows its increments "
                        "whatever breaks, for load histories (loading, "
                        "unloading, reloading).");
      prm.declare_entry("Residual tolerance",
                        "1e-9",
                        Double(0.),
                        "Equilibrium iterations stop when |r| <= tol * "
                        "max(|r_0|, |f_ext|, |f_int|); |f_int| includes the "
                        "reactions, the force scale of displacement-driven "
                        "runs.");
      prm.declare_entry("Max iterations",
                        "10",
                        Integer(1),
                        "Equilibrium iterations per load step before the run "
                        "stops with exit state 'diverged' (newton: before the "
                        "step is cut).");
      prm.declare_entry("Max step cuts",
                        "4",
                        Integer(0),
                        "newton: cuts of the load increment in a row (two "
                        "converged steps undo one) before the run stops with "
                        "exit state 'unstable'.");
      prm.declare_entry("Step cut factor",
                        "0.25",
                        Double(0., 1.),
                        "newton: a cut multiplies the load increment by this "
                        "(0 < factor < 1).");
      prm.declare_entry("Arc length steps",
                        "50",
                        Integer(1),
                        "arc length: steps along the path (the run also ends "
                        "when the load factor reaches 1). The first step is "
                        "load-controlled, 1 / Load steps; its displacement "
                        "increment sets the arc length.");
      prm.declare_entry("Line search",
                        "true",
                        Bool(),
                        "newton: backtracking on the residual norm.");
      prm.declare_entry("Stability check",
                        "true",
                        Bool(),
                        "newton: test every converged state for stability "
                        "(reduced tangent positive definite); an unstable "
                        "state is rejected like a diverged step.");
      prm.declare_entry("Time step",
                        "auto",
                        Anything(),
                        "Dynamic runs: the time step [s], > 0, or 'auto' "
                        "(explicit only): 'Time step safety factor' times "
                        "the critical step 2/omega_max, omega_max^2 the "
                        "largest eigenvalue of M^-1 K by power iteration.");
      prm.declare_entry("End time",
                        "0",
                        Double(),
                        "Dynamic runs: the end time [s], > 0.");
      prm.declare_entry("Time step safety factor",
                        "0.9",
                        Double(),
                        "Explicit, automatic step: dt = factor * 2/omega_max, "
                        "0 < factor; above 1 the run is unstable (a note "
                        "says so).");
      prm.declare_entry("Eigenvalue iterations",
                        "50",
                        Integer(1),
                        "Power iterations for omega_max^2, the largest "
                        "eigenvalue of M^-1 K.");
      prm.declare_entry("Newmark beta",
                        "0.25",
                        Double(),
                        "Newmark beta: unconditionally stable for "
                        "beta >= (2 gamma + 1)^2 / 16 (0.25 with gamma = "
                        "0.5: average acceleration).");
      prm.declare_entry("Newmark gamma",
                        "0.5",
                        Double(),
                        "Newmark gamma >= 0.5 (0.5: no numerical damping; "
                        "larger values damp high frequencies).");
      prm.declare_entry("HHT alpha",
                        "0",
                        Double(),
                        "Newmark: HHT-alpha numerical damping of high "
                        "frequencies, -1/3 <= alpha <= 0 (0: none). If not 0, "
                        "beta = (1 - alpha)^2 / 4 and gamma = 1/2 - alpha "
                        "replace 'Newmark beta' and 'Newmark gamma'.");
      prm.declare_entry("Mass",
                        "lumped",
                        Selection("lumped|consistent"),
                        "lumped: FE row-sum lumping over the FE cells plus "
                        "rho V^pd over the PD cells, one value per node. "
                        "consistent (newmark only): the consistent FE mass "
                        "plus the PD lumped mass.");
      prm.declare_entry("Reuse factorization",
                        "true",
                        Bool(),
                        "Newmark: factorise M + beta dt^2 K once and reuse it "
                        "while no bond breaks (false: every step, as the "
                        "peer code does; for benchmarks).");
      prm.declare_entry("Initial velocity",
                        "",
                        Anything(),
                        "Dynamic runs: dim expressions of x, y, z separated "
                        "by ';' (empty: at rest) [m/s].");
      prm.declare_entry("Energy tolerance",
                        "0.5",
                        Double(),
                        "Dynamic runs stop with exit state 'time step too "
                        "large' when kinetic + strain + dissipated energy "
                        "exceeds the initial energy plus the external work "
                        "by more than this fraction of the largest energy "
                        "supplied so far (> 0).");
      prm.declare_entry("History interval",
                        "1",
                        Integer(1),
                        "Dynamic runs: a history.csv row every this many "
                        "steps (and at the last step).");
      prm.declare_entry("Monitor points",
                        "",
                        Anything(),
                        "Dynamic runs: 'name: (x, y[, z])' separated by ';'; "
                        "the displacement of the node nearest to each point "
                        "goes into history.csv as u_<name>_<component>.");
      prm.enter_subsection("Dynamic relaxation");
      prm.declare_entry("Density factor",
                        "1",
                        Double(),
                        "The fictitious density of every DoF is this times "
                        "the Gershgorin bound 1/4 sum_j |K_ij| of the "
                        "tangent at the start of each load step (> 0; >= 1 "
                        "is stable for a linear model).");
      prm.declare_entry("Damping",
                        "adaptive",
                        Anything(),
                        "adaptive: c = 2 sqrt(u^T K_local u / u^T u) from the "
                        "local Rayleigh quotient at every iteration (Kilic & "
                        "Madenci); or a fixed coefficient 0 <= c < 2.");
      prm.declare_entry("Ramp iterations",
                        "0",
                        Integer(0),
                        "The load factor of a step goes from the previous "
                        "step's to its own over this many iterations "
                        "(prescribed displacements move at a finite rate, "
                        "as in the paper's m/iteration loading; 0: at once, "
                        "which can tear the bonds next to a moved boundary "
                        "before the body follows).");
      prm.declare_entry("Max iterations",
                        "100000",
                        Integer(1),
                        "Relaxation iterations per load step before the run "
                        "stops with exit state 'diverged'.");
      prm.leave_subsection();
      prm.enter_subsection("Adaptive");
      prm.declare_entry("Implicit steps",
                        "5",
                        Integer(1),
                        "N_i: Newton's load increment is 1/N_i (cut where "
                        "a step fails; specs/003 §4).");
      prm.declare_entry("Explicit steps",
                        "100",
                        Integer(1),
                        "N_e: the load left at the first switch to "
                        "dynamic relaxation, 1 - t_n, is applied in N_e "
                        "increments, each relaxed to equilibrium (with "
                        "Dynamic relaxation/Ramp iterations).");
      prm.declare_entry("Switch to explicit",
                        "onset",
                        Selection("onset|newton failure"),
                        "onset: after the first Newton state in which more "
                        "bonds than before stretch beyond Onset fraction * "
                        "s_m (the paper's rule), or where Newton fails; "
                        "newton failure: only where Newton fails with its "
                        "smallest step.");
      prm.declare_entry("Onset state",
                        "discard",
                        Selection("discard|keep"),
                        "The Newton state in which the switch to explicit "
                        "is detected: discard (relax from the state before "
                        "it: Newton's long step may have jumped deep into "
                        "the degradation) or keep (relax from it, the "
                        "paper's choice, specs/003 §4 [AMB] (a)).");
      prm.declare_entry("Onset fraction",
                        "1",
                        Double(),
                        "The switch threshold stretch as a fraction of the "
                        "onset stretch s_m (0 < f <= 1; below 1 switches "
                        "before any bond degrades).");
      prm.declare_entry("Switch to implicit",
                        "quiet",
                        Selection("quiet|never"),
                        "quiet: back to Newton after Quiet steps explicit "
                        "increments in a row in which no bond passed the "
                        "threshold and the degradation sum(1 - T) changed "
                        "by at most Damage tolerance (relative); never: "
                        "explicit to the end (the paper leaves the rule "
                        "open, specs/003 §4).");
      prm.declare_entry("Quiet steps",
                        "",
                        Anything(),
                        "The quiet window of 'Switch to implicit = quiet' "
                        "(an integer >= 1; no default: the rule needs it).");
      prm.declare_entry("Damage tolerance",
                        "",
                        Anything(),
                        "The largest relative change of sum(1 - T) in a "
                        "quiet increment (a number > 0; no default: the "
                        "rule needs it).");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    Settings::parse(ParameterHandler &prm, const std::string &file, int dim)
    {
      prm.enter_subsection("Driver");
      type                    = prm.get("Type");
      load_steps              = prm.get_integer("Load steps");
      load_increment          = prm.get_double("Load increment");
      initial_load            = prm.get_double("Initial load");
      jump_to_critical_load   = prm.get_bool("Jump to critical load");
      hold_load_while_growing = prm.get_bool("Hold load while cracks grow");
      max_step_cuts           = prm.get_integer("Max step cuts");
      step_cut_factor         = prm.get_double("Step cut factor");
      line_search             = prm.get_bool("Line search");
      arc_length_steps        = prm.get_integer("Arc length steps");
      stability_check         = prm.get_bool("Stability check");
      residual_tolerance      = prm.get_double("Residual tolerance");
      max_iterations          = prm.get_integer("Max iterations");
      time_step_text          = trim(prm.get("Time step"));
      end_time                = prm.get_double("End time");
      safety_factor           = prm.get_double("Time step safety factor");
      eigenvalue_iterations   = prm.get_integer("Eigenvalue iterations");
      newmark_beta            = prm.get_double("Newmark beta");
      newmark_gamma           = prm.get_double("Newmark gamma");
      hht_alpha               = prm.get_double("HHT alpha");
      mass                    = prm.get("Mass");
      reuse_factorization     = prm.get_bool("Reuse factorization");
      initial_velocity        = split(prm.get("Initial velocity"), ';');
      energy_tolerance        = prm.get_double("Energy tolerance");
      history_interval        = prm.get_integer("History interval");
      monitor_points_text     = prm.get("Monitor points");
      prm.enter_subsection("Dynamic relaxation");
      relaxation_density_factor  = prm.get_double("Density factor");
      relaxation_damping         = trim(prm.get("Damping"));
      relaxation_max_iterations  = prm.get_integer("Max iterations");
      relaxation_ramp_iterations = prm.get_integer("Ramp iterations");
      prm.leave_subsection();
      prm.enter_subsection("Adaptive");
      adaptive_implicit_steps        = prm.get_integer("Implicit steps");
      adaptive_explicit_steps        = prm.get_integer("Explicit steps");
      adaptive_to_explicit           = prm.get("Switch to explicit");
      adaptive_onset_fraction        = prm.get_double("Onset fraction");
      adaptive_onset_state           = prm.get("Onset state");
      adaptive_to_implicit           = prm.get("Switch to implicit");
      adaptive_quiet_steps_text      = trim(prm.get("Quiet steps"));
      adaptive_damage_tolerance_text = trim(prm.get("Damage tolerance"));
      prm.leave_subsection();
      prm.leave_subsection();
      if (!(step_cut_factor > 0. && step_cut_factor < 1.))
        throw InputError(file,
                         "Driver/Step cut factor",
                         number(step_cut_factor) + " is not between 0 and 1",
                         "0 < factor < 1");
    }

    void
    Settings::check_time_stepping(const std::string &file,
                                  const int          dim,
                                  const bool         automatic_step)
    {
      const std::string p = "Driver/";
      if (time_step_text == "auto")
        time_step = 0.;
      else if (!time_step_text.empty()) // else: set directly, not parsed
        {
          std::size_t end = 0;
          try
            {
              time_step = std::stod(time_step_text, &end);
            }
          catch (...)
            {
              end = 0;
            }
          if (end != time_step_text.size() || !(time_step > 0.))
            throw InputError(file,
                             p + "Time step",
                             "'" + time_step_text +
                               "' is not a positive time step",
                             automatic_step ? "dt > 0 [s], or 'auto'" :
                                              "dt > 0 [s]");
        }
      if (!(end_time > 0.))
        throw InputError(file,
                         p + "End time",
                         "end time = " + number(end_time) + " is not positive",
                         "end time > 0 [s]");
      if (!(safety_factor > 0.))
        throw InputError(file,
                         p + "Time step safety factor",
                         number(safety_factor) + " is not positive",
                         "factor > 0 (0.9 by default; above 1 is unstable)");
      if (!(hht_alpha >= -1. / 3. - 1e-14 && hht_alpha <= 0.))
        throw InputError(file,
                         p + "HHT alpha",
                         "alpha = " + number(hht_alpha) +
                           " is outside the range of the HHT method",
                         "-1/3 <= alpha <= 0");
      if (!initial_velocity.empty() &&
          static_cast<int>(initial_velocity.size()) != dim)
        throw InputError(file,
                         p + "Initial velocity",
                         "needs " + std::to_string(dim) + " expressions, got " +
                           std::to_string(initial_velocity.size()),
                         "empty, or dim expressions separated by ';'");
      for (const auto &e : initial_velocity)
        check_expression(e, file, p + "Initial velocity");
      if (!(energy_tolerance > 0.))
        throw InputError(file,
                         p + "Energy tolerance",
                         number(energy_tolerance) + " is not positive",
                         "tolerance > 0");
      if (!monitor_points_text.empty())
        monitor_points.clear();
      for (const std::string &item : split(monitor_points_text, ';'))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            throw InputError(file,
                             p + "Monitor points",
                             "cannot read '" + item + "'",
                             "'name: (x, y[, z])' separated by ';'");
          MonitorPoint m;
          m.name  = trim(item.substr(0, colon));
          m.point = parse_point(trim(item.substr(colon + 1)),
                                file,
                                p + "Monitor points",
                                dim);
          monitor_points.push_back(m);
        }
    }
  } // namespace Drivers
} // namespace pdfem
