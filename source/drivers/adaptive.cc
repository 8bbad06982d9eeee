// SPDX-License-Identifier: LGPL-2.1-or-later
// The `adaptive` driver: Newton while the bonds are elastic, dynamic
// relaxation while they degrade (specs/003 §4).
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/drivers/dynamic_relaxation.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/drivers/newton_driver.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

namespace pdfem
{
  namespace Drivers
  {
    namespace
    {
      /// The integer >= 1 in @p text, or InputError naming the parameter.
      unsigned int
      parse_quiet_steps(const std::string &text, const std::string &file)
      {
        double n = 0.;
        if (!ParameterTools::parse_number(text, n) || n < 1. ||
            n != std::floor(n) || n > 1e9)
          throw InputError(file,
                           "Driver/Adaptive/Quiet steps",
                           text.empty() ?
                             "the switching rule 'Switch to implicit = "
                             "quiet' has no quiet window" :
                             "'" + text + "' is not an integer >= 1",
                           "an integer >= 1, or Switch to implicit = never");
        return static_cast<unsigned int>(n);
      }

      /// The number > 0 in @p text, or InputError naming the parameter.
      double
      parse_damage_tolerance(const std::string &text, const std::string &file)
      {
        double v = 0.;
        if (!ParameterTools::parse_number(text, v) || !(v > 0.))
          throw InputError(file,
                           "Driver/Adaptive/Damage tolerance",
                           text.empty() ?
                             "the switching rule 'Switch to implicit = "
                             "quiet' has no damage tolerance" :
                             "'" + text + "' is not a number > 0",
                           "a relative tolerance > 0 (e.g. 1e-3), or Switch "
                           "to implicit = never");
        return v;
      }

      /**
       * The adaptive explicit-implicit scheme of Hu et al. (specs/003 §4)
       * for models whose bonds degrade smoothly (bond based, Degradation =
       * tanh), as a driver over the library's Newton (NewtonDriver) and
       * dynamic relaxation (DynamicRelaxation):
       *
       * - implicit: Newton with the load increment 1 / N_i (`Implicit
       *   steps`, cut where a step fails) while no further bond stretches
       *   beyond f s_m (`Onset fraction` f); the first state in which one
       *   does is discarded or kept (`Onset state`, specs/003 [AMB] (a))
       *   and the run switches, from the last state kept, to
       * - explicit: the load left at the first switch, 1 - t_n, in N_e
       *   equal increments (`Explicit steps`), each relaxed to equilibrium
       *   (the paper's explicit increment (1 - n / N_i) u / N_e; one
       *   increment is a relaxed load step, [AMB] (b)), until for
       *   `Quiet steps` increments in a row no bond passed f s_m and the
       *   degradation D = sum_bonds (1 - T) changed by at most `Damage
       *   tolerance` relative ([AMB]: the paper's "no more bonds fail over
       *   an extended period"); then implicit again with 1 / N_i ([AMB]
       *   (c)), back to explicit if the damage grows again.
       *
       * Where Newton fails with its smallest step (a limit point of the
       * softening body), the run switches to explicit as well, from the
       * last converged state. Every switch is a progress line; history.csv
       * gets `method` (0 Newton, 1 relaxation) and `switched` (1 on the
       * first row after a switch), `degrading_bonds` (bonds beyond the
       * threshold, both directions) and `degradation` (D).
       */
      class AdaptiveRun : public Interface
      {
      public:
        void
        initialize(const Settings    &settings,
                   const std::string &file,
                   const int          dim) override
        {
          Interface::initialize(settings, file, dim);
          check_relaxation_settings(settings, file);
          const double f = settings.adaptive_onset_fraction;
          if (!(f > 0. && f <= 1.))
            throw InputError(file,
                             "Driver/Adaptive/Onset fraction",
                             number(f) + " is not in (0, 1]",
                             "0 < f <= 1 (1: the onset stretch s_m itself)");
          if (settings.adaptive_to_implicit == "quiet")
            {
              quiet_steps =
                parse_quiet_steps(settings.adaptive_quiet_steps_text, file);
              damage_tolerance =
                parse_damage_tolerance(settings.adaptive_damage_tolerance_text,
                                       file);
            }
        }

        bool
        needs_assembled_matrix() const override
        {
          return true;
        }

        void
        check(const RunTraits &traits) const override
        {
          Interface::check(traits);
          check_relaxation_traits(traits);
          if (!traits.smooth_degradation &&
              parameters.adaptive_to_explicit == "onset")
            throw InputError(traits.file,
                             "Driver/Adaptive/Switch to explicit",
                             "'onset' switches where bonds start to "
                             "degrade; the " +
                               traits.model_name +
                               " model has no degradation onset",
                             "Peridynamics/Model = bond based with Bond "
                             "based/Degradation = tanh, or Switch to "
                             "explicit = newton failure");
        }

        bool
        handles_nonlinear_models() const override
        {
          return true;
        }

        unsigned int
        planned_steps() const override
        {
          return 0; // the switches decide
        }

        std::vector<std::string>
        history_columns() const override
        {
          return {"method", "switched", "degrading_bonds", "degradation"};
        }

        void
        history_values(std::vector<double> &row) const override
        {
          row.push_back(explicit_mode ? 1. : 0.);
          row.push_back(switched_row ? 1. : 0.);
          row.push_back(double(state.n_beyond_threshold));
          row.push_back(state.degradation);
        }

        bool
        resumable() const override
        {
          return true;
        }

        void
        run(Host &host) override
        {
          newton_driver     = std::make_unique<NewtonDriver>(parameters);
          relaxation_driver = std::make_unique<DynamicRelaxation>(parameters);
          NewtonDriver      &newton     = *newton_driver;
          DynamicRelaxation &relaxation = *relaxation_driver;
          newton.set_progress(host.progress_pulse());
          relaxation.set_progress(host.progress_pulse());
          const double f        = parameters.adaptive_onset_fraction;
          const bool   on_onset = parameters.adaptive_to_explicit == "onset";
          const bool   discard_onset_state =
            parameters.adaptive_onset_state == "discard";
          double       onset_load             = 0.;
          double       t                      = 0.;
          unsigned int step                   = 1;
          state                               = host.degradation_state(f);
          PDModels::DegradationState baseline = state;
          // in the explicit stage; a step was recorded since the last
          // checkpoint boundary
          bool       in_explicit = false, recorded = false;
          const auto record_step = [&](const StepRecord &record,
                                       const bool        in_explicit) {
            switched_row  = in_explicit != explicit_mode;
            explicit_mode = in_explicit;
            (in_explicit ? n_explicit_steps : n_implicit_steps) += 1;
            if (!in_explicit)
              newton_iterations += record.newton_iterations;
            host.after_equilibrium(record, false);
            t        = record.load_factor;
            step     = record.step + 1;
            recorded = true;
          };
          // Checkpoint and restart: the scheme's own state beside the Newton
          // span's (when the boundary is inside one: its first step and
          // load factor, so that a restart goes on with the same span).
          const StateArchive *restart = host.restart_state();
          const auto          save = [&](StateArchive &a, const bool in_span) {
            a.put("adaptive/explicit", in_explicit);
            a.put("adaptive/in span", in_span);
            a.put("adaptive/load factor", t);
            a.put("adaptive/step", step);
            a.put("adaptive/baseline", baseline);
            a.put("adaptive/state", state);
            a.put("adaptive/explicit row", explicit_mode);
            a.put("adaptive/switched row", switched_row);
            a.put("adaptive/quiet", n_quiet);
            a.put("adaptive/counts",
                  std::vector<unsigned long>{n_implicit_steps,
                                             n_explicit_steps,
                                             n_switches,
                                             newton_iterations,
                                             n_cuts,
                                             first_switch_step,
                                             relaxation.iterations()});
            a.put("adaptive/first switch load", first_switch_load);
          };
          if (restart)
            {
              const StateArchive &a = *restart;
              in_explicit           = a.get<bool>("adaptive/explicit");
              t                     = a.get<double>("adaptive/load factor");
              step                  = a.get<unsigned int>("adaptive/step");
              baseline = a.get<PDModels::DegradationState>("adaptive/baseline");
              state    = a.get<PDModels::DegradationState>("adaptive/state");
              explicit_mode = a.get<bool>("adaptive/explicit row");
              switched_row  = a.get<bool>("adaptive/switched row");
              n_quiet       = a.get<unsigned int>("adaptive/quiet");
              const auto counts =
                a.get_vector<unsigned long>("adaptive/counts");
              if (counts.size() != 7)
                throw InputError("",
                                 "--restart",
                                 "the checkpoint's adaptive state is damaged");
              n_implicit_steps  = counts[0];
              n_explicit_steps  = counts[1];
              n_switches        = counts[2];
              newton_iterations = counts[3];
              n_cuts            = counts[4];
              first_switch_step = counts[5];
              relaxation.resume_iterations(counts[6]);
              first_switch_load = a.get<double>("adaptive/first switch load");
              if (!a.get<bool>("adaptive/in span"))
                restart = nullptr; // no Newton span to go on with
            }
          const auto announce = [&](const std::string &to,
                                    const std::string &why) {
            ++n_switches;
            std::ostringstream s;
            s << "  switch to " << to << " after step " << step - 1
              << " (t = " << t << "): " << why;
            host.report(s.str());
          };

          while (t < 1. - 1e-12)
            {
              if (!in_explicit)
                {
                  NewtonDriver::Span span;
                  span.begin      = t;
                  span.increment  = 1. / parameters.adaptive_implicit_steps;
                  span.first_step = step;
                  span.follow_snap_backs = false;
                  if (restart)
                    {
                      span.begin = restart->get<double>("adaptive/span begin");
                      span.first_step =
                        restart->get<unsigned int>("adaptive/span first step");
                      span.resume.from = restart;
                      restart          = nullptr;
                    }
                  span.resume.boundary =
                    [&, span_begin = span.begin, span_first = span.first_step](
                      const SaveState &newton_save) {
                      host.step_boundary([&](StateArchive &a) {
                        newton_save(a);
                        save(a, true);
                        a.put("adaptive/span begin", span_begin);
                        a.put("adaptive/span first step", span_first);
                      });
                      recorded = false;
                    };
                  // The onset test on each converged Newton state, before
                  // it is accepted (discarded) or after (kept).
                  bool                       onset = false;
                  PDModels::DegradationState probe;
                  span.stop_before = [&](const StepRecord &record) {
                    probe = host.degradation_state(f);
                    onset = on_onset && probe.n_beyond_threshold >
                                          baseline.n_beyond_threshold;
                    onset_load = record.load_factor;
                    return onset && discard_onset_state;
                  };
                  span.stop_after = [&](const StepRecord &) { return onset; };
                  try
                    {
                      newton.run(
                        host.system(),
                        host.solution(),
                        [&](const StepRecord &record) {
                          state = probe;
                          record_step(record, false);
                        },
                        host.stability(),
                        host.load_derivative(false),
                        span);
                    }
                  catch (const RunFailure &failure)
                    {
                      if (failure.exit_state != "unstable")
                        throw;
                      onset = false;
                      announce("dynamic relaxation",
                               "Newton failed with its smallest step");
                      in_explicit = true;
                    }
                  n_cuts += newton.outcome().n_cuts;
                  if (onset)
                    {
                      std::ostringstream why;
                      why << "at t = " << onset_load << " "
                          << probe.n_beyond_threshold -
                               baseline.n_beyond_threshold
                          << " more bond(s) stretched beyond " << f
                          << " s_m (largest s/s_m " << probe.max_onset_ratio
                          << ")"
                          << (discard_onset_state ? "; that state discarded" :
                                                    "");
                      announce("dynamic relaxation", why.str());
                      in_explicit = true;
                    }
                  if (in_explicit && first_switch_load < 0.)
                    {
                      first_switch_load = t;
                      first_switch_step = step - 1;
                    }
                  continue;
                }
              // explicit: relaxed increments of (1 - t_n) / N_e
              if (recorded)
                host.step_boundary([&](StateArchive &a) { save(a, false); });
              recorded = false;
              const double dt =
                (1. - first_switch_load) / parameters.adaptive_explicit_steps;
              const double t_new = t + dt > 1. - 1e-12 ? 1. : t + dt;
              const PDModels::DegradationState before = state;
              const StepRecord                 record = relaxation.relax(
                host.system(), host.solution(), t_new, t, step);
              state = host.degradation_state(f);
              const bool quiet =
                state.n_beyond_threshold == before.n_beyond_threshold &&
                std::abs(state.degradation - before.degradation) <=
                  damage_tolerance *
                    std::max(state.degradation, before.degradation);
              n_quiet = quiet ? n_quiet + 1 : 0;
              record_step(record, true);
              if (parameters.adaptive_to_implicit == "quiet" &&
                  n_quiet >= quiet_steps && t < 1. - 1e-12)
                {
                  std::ostringstream why;
                  why << "the damage did not grow in " << n_quiet
                      << " increment(s) (" << state.n_beyond_threshold
                      << " bonds beyond the threshold, degradation "
                      << state.degradation << ")";
                  announce("Newton", why.str());
                  baseline    = state;
                  in_explicit = false;
                  n_quiet     = 0;
                }
            }
        }

        void
        write_summary(IO::JsonWriter &json) const override
        {
          json.value("implicit_steps", n_implicit_steps);
          json.value("explicit_steps", n_explicit_steps);
          json.value("switches", n_switches);
          json.value("first_switch_step", first_switch_step);
          json.value("first_switch_load_factor",
                     std::max(0., first_switch_load));
          json.value("newton_iterations", newton_iterations);
          json.value("step_cuts", n_cuts);
          json.value("relaxation_iterations",
                     relaxation_driver ? relaxation_driver->iterations() : 0ul);
          json.value("degrading_bonds", state.n_beyond_threshold);
          json.value("failed_bonds", state.n_failed);
          json.value("degradation", state.degradation);
        }

        std::map<std::string, double>
        timings() const override
        {
          std::map<std::string, double> t;
          for (const DriverTimings *d :
               {newton_driver ? &newton_driver->timings() : nullptr,
                relaxation_driver ? &relaxation_driver->timings() : nullptr})
            for (const auto &[phase, seconds] : phase_timings(d))
              t[phase] += seconds;
          return t;
        }

      private:
        unsigned int quiet_steps      = 0;
        double       damage_tolerance = 0.;

        // the run (for history rows and the summary)
        std::unique_ptr<NewtonDriver>      newton_driver;
        std::unique_ptr<DynamicRelaxation> relaxation_driver;
        PDModels::DegradationState         state;
        bool                               explicit_mode     = false;
        bool                               switched_row      = false;
        unsigned int                       n_quiet           = 0;
        unsigned long                      n_implicit_steps  = 0;
        unsigned long                      n_explicit_steps  = 0;
        unsigned long                      n_switches        = 0;
        unsigned long                      newton_iterations = 0;
        unsigned long                      n_cuts            = 0;
        unsigned long                      first_switch_step = 0;
        double                             first_switch_load = -1.;
      };
    } // namespace

    PDFEM_REGISTER_DRIVER(
      AdaptiveRun,
      "adaptive",
      "Hu et al.'s explicit-implicit scheme: Newton while no bond stretches "
      "beyond the degradation onset, dynamic relaxation while bonds degrade, "
      "Newton again once the damage stops growing (bond based with "
      "Degradation = tanh).")
  } // namespace Drivers
} // namespace pdfem
