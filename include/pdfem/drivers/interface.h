// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_INTERFACE_H
#define PDFEM_DRIVERS_INTERFACE_H

#include <pdfem/base/plugins.h>
#include <pdfem/drivers/dynamics.h>
#include <pdfem/drivers/newton_driver.h>
#include <pdfem/drivers/progress_pulse.h>
#include <pdfem/drivers/quasi_static_driver.h>
#include <pdfem/drivers/resume.h>
#include <pdfem/drivers/settings.h>
#include <pdfem/drivers/static_driver.h>
#include <pdfem/pd_models/degradation_state.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    class JsonWriter;
  }

  namespace Drivers
  {
    /**
     * What a driver sees of the run it drives; the Simulator implements it
     * (and a program may, to drive a system of its own). No dimension: the
     * driver only moves vectors.
     */
    class Host
    {
    public:
      virtual ~Host() = default;

      /// The discretised problem. A crack criterion may replace it between
      /// steps (a larger PD region, same DoFs): ask again after each step.
      virtual SystemInterface &
      system() = 0;

      /// The same problem with its mass, for time integrators. The driver's
      /// check() has made sure that the model has one.
      virtual DynamicSystemInterface &
      dynamic_system() = 0;

      /// The unknowns: initial guess in, solution out.
      virtual SystemInterface::Vector &
      solution() = 0;

      /// The initial velocity v0 (zero unless the scene gives one).
      virtual void
      initial_velocity(SystemInterface::Vector &v0) = 0;

      /// The stability test of a nonlinear model (nullptr: none).
      virtual StabilityInterface *
      stability()
      {
        return nullptr;
      }

      /**
       * d r / d t of a model whose loads are linear in t, for following
       * the path past limit points: always for @p arc_length, else only
       * where the host wants the snap-back continuation of hard loading
       * (empty: none).
       */
      virtual NewtonDriver::LoadDerivative
      load_derivative(bool arc_length)
      {
        (void)arc_length;
        return {};
      }

      /**
       * After each converged equilibrium: the crack criterion (which may
       * break bonds when @p allow_growth) and the postprocessors (a
       * history row, field output). Returns what the criterion did.
       */
      virtual GrowthCheck
      after_equilibrium(const StepRecord &record, bool allow_growth) = 0;

      /// After each stability test of a converged state (newton, arc
      /// length).
      virtual void
      after_stability_check(const StabilityReport &)
      {}

      /// Dynamic runs: after each time step, before it is recorded: the
      /// crack criterion at (u, t). Returns whether bonds broke.
      virtual bool
      after_time_step(const SystemInterface::Vector &u, double t) = 0;

      /// Dynamic runs: a time step is complete (history, progress).
      virtual void
      record_time_step(const DynamicRecord &record) = 0;

      /**
       * Between two steps of a resumable driver (Interface::resumable()):
       * @p save puts the driver's state into an archive. The host writes a
       * checkpoint of the whole run when one is due, and ends the run here
       * (RunFailure "interrupted", after the checkpoint) when a signal
       * asked it to.
       */
      virtual void
      step_boundary(const SaveState &save)
      {
        (void)save;
      }

      /// How far the PD model's smooth degradation has gone at solution()
      /// (threshold: @p onset_fraction times the onset stretch; all 0
      /// unless the model degrades smoothly, RunTraits::smooth_degradation).
      /// Collective.
      virtual PDModels::DegradationState
      degradation_state(double onset_fraction)
      {
        (void)onset_fraction;
        return {};
      }

      /// A line of progress output from the driver (e.g. a switch of
      /// method), printed unless the run is quiet.
      virtual void
      report(const std::string &line)
      {
        (void)line;
      }

      /// Lines from inside long steps, through report() at the run's
      /// `Output/Progress interval` (none for a quiet run).
      virtual ProgressPulse
      progress_pulse()
      {
        return {};
      }

      /// The driver's state in the checkpoint this run restarts from
      /// (nullptr: a fresh start).
      virtual const StateArchive *
      restart_state() const
      {
        return nullptr;
      }
    };

    /// The Resume of a driver loop that @p host runs: its restart state and
    /// its step boundaries.
    inline Resume
    resume_through(Host &host)
    {
      Resume resume;
      resume.from     = host.restart_state();
      resume.boundary = [&host](const SaveState &save) {
        host.step_boundary(save);
      };
      return resume;
    }

    /** What a driver may check of the rest of a run before it starts. */
    struct RunTraits
    {
      /// The input file, for messages.
      std::string file;
      int         dim = 2;
      /// The PD model needs Newton iterations (its forces are nonlinear).
      bool nonlinear_model = false;
      /// The material has a positive density (a mass matrix exists).
      bool has_mass = false;
      /// The linear solver assembles the coupled matrix (not 'amg fe').
      bool assembled_matrix = true;
      /// The PD model gives its tangent row by row (tangent_row()), so
      /// that the matrix-free path bounds the tangent's rows without
      /// assembling it (SystemInterface::stiffness_row_bounds()).
      bool tangent_rows = false;
      /// The PD model degrades smoothly (Host::degradation_state() is
      /// available).
      bool smooth_degradation = false;
      /// The model's name and the driver's own, for messages.
      std::string model_name;
      std::string driver_name;
    };

    /**
     * A driver plugin: how loads or time advance and when equilibrium is
     * sought (specs/004 §2). Register one with PDFEM_REGISTER_DRIVER at the
     * end of its `.cc` file; it is then a choice of `Driver/Type`.
     *
     * The parameters of every driver live in `subsection Driver` (Settings
     * declares them); a plugin parses them and validates what it needs.
     */
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /// Read `subsection Driver` (Settings::parse), then initialize().
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &file,
                       int                       dim);

      /**
       * Take @p settings (parsed, or translated from a PDLSM-FEM command
       * file) and validate what this driver needs of them (InputError
       * naming @p file and the parameter).
       */
      virtual void
      initialize(const Settings &settings, const std::string &file, int dim);

      /// Throw InputError if the run cannot be driven by this driver (by
      /// default: a nonlinear model needs handles_nonlinear_models()).
      virtual void
      check(const RunTraits &traits) const;

      /// Can the driver solve a nonlinear model (Newton with a tangent)?
      virtual bool
      handles_nonlinear_models() const
      {
        return false;
      }

      /// Does the driver need the PD model's tangent (a stiffness or its
      /// diagonal blocks)? A model of forces only
      /// (PDModels::Layout::tangent = false) is refused with such a driver.
      virtual bool
      needs_tangent() const
      {
        return true;
      }

      /// Does the driver work with the assembled matrix itself (factorise
      /// it, read its rows)? Linear solver Type = auto then takes the
      /// direct path (Solvers::Settings::resolve()).
      virtual bool
      needs_assembled_matrix() const
      {
        return false;
      }

      /**
       * Are all of the driver's uses of the tangent linear solves, so that
       * matrix-free CG (Solvers::Settings::solves_with_products_only()),
       * which applies the operator by force evaluations, can stand in for
       * it? A linear, symmetric model of forces only may then run with
       * this driver although needs_tangent() is true.
       */
      virtual bool
      solves_with_products() const
      {
        return false;
      }

      /**
       * Does the driver solve linear systems with the tangent (static
       * equilibria, Newton steps)? Set-up then builds the matrix-free
       * path's preconditioner before the PD model's per-bond data
       * (Coupling::Settings::prepare_solver).
       */
      virtual bool
      solves_linear_systems() const
      {
        return false;
      }

      /// Remarks for stderr before the run (e.g. an unstable choice).
      virtual std::vector<std::string>
      notes() const
      {
        return {};
      }

      /// Does the driver integrate in time (history rows are time steps)?
      virtual bool
      dynamic() const
      {
        return false;
      }

      /**
       * Can a run of this driver be checkpointed and restarted
       * (Host::step_boundary(), Host::restart_state())? Its loop state
       * between two steps must then be complete in what it saves.
       */
      virtual bool
      resumable() const
      {
        return false;
      }

      /// Does the driver grow cracks (so that a criterion may break bonds
      /// after each equilibrium)?
      virtual bool
      grows_cracks() const
      {
        return false;
      }

      /// The number of steps the run will record if it completes (0: not
      /// known in advance; progress then estimates the time left by load).
      virtual unsigned int
      planned_steps() const
      {
        return parameters.load_steps;
      }

      /// The driver's own history.csv columns (after the first ones).
      virtual std::vector<std::string>
      history_columns() const
      {
        return {};
      }

      /// Their values for the row being recorded (appended to @p row).
      virtual void
      history_values(std::vector<double> &row) const
      {
        (void)row;
      }

      /// Run: @p host gives the system and receives every step.
      virtual void
      run(Host &host) = 0;

      /// Add the driver's own members to summary.json: its "final" object
      /// (static drivers) or its "dynamics" section (dynamic ones).
      virtual void
      write_summary(IO::JsonWriter &json) const;

      /// Wall seconds per phase ("assembly", "solve", and for dynamic
      /// runs the per-step figures).
      virtual std::map<std::string, double>
      timings() const = 0;

      /// A progress line's end after the first step (e.g. the time step).
      virtual std::string
      first_step_note(const DynamicRecord &) const
      {
        return "";
      }

      /// Newton drivers: why and where the run stopped (nullptr: not one).
      virtual const NewtonOutcome *
      outcome() const
      {
        return nullptr;
      }

      /// The parsed parameters.
      const Settings &
      settings() const
      {
        return parameters;
      }

    protected:
      Settings parameters;
    };

    /// "assembly" and "solve" of @p t (none if @p t is nullptr: the driver
    /// has not run).
    inline std::map<std::string, double>
    phase_timings(const DriverTimings *t)
    {
      if (t == nullptr)
        return {};
      return {{"assembly", t->assembly}, {"solve", t->solve}};
    }

    /// The registry of drivers.
    Plugins::Registry<Interface> &
    registry();

    /// The driver @p name (InputError naming `Driver/Type` if unknown).
    std::unique_ptr<Interface>
    create(const std::string &name, const std::string &file);
  } // namespace Drivers
} // namespace pdfem

/**
 * Register the driver class @p classname under @p name (a `Driver/Type`
 * value) with a one-line @p description; at namespace scope in its `.cc`.
 */
#define PDFEM_REGISTER_DRIVER(classname, name, description)              \
  namespace                                                              \
  {                                                                      \
    const bool PDFEM_PLUGIN_CONCAT(pdfem_driver_registered_, __LINE__) = \
      ::pdfem::Drivers::registry().add(                                  \
        name,                                                            \
        description,                                                     \
        {},                                                              \
        []() -> std::unique_ptr<::pdfem::Drivers::Interface> {           \
          return std::make_unique<classname>();                          \
        });                                                              \
  }

#endif
