// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the simulator module: the state of a run and the driver host
// it implements.
#ifndef PDFEM_SOURCE_SIMULATOR_SIMULATOR_IMPL_H
#define PDFEM_SOURCE_SIMULATOR_SIMULATOR_IMPL_H

#include <pdfem/base/state_archive.h>
#include <pdfem/io/history.h>
#include <pdfem/simulator/postprocess.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace pdfem
{
  namespace internal
  {
    /// Wall seconds since @p start.
    inline double
    seconds_since(const std::chrono::steady_clock::time_point &start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }

    /// Restores a stream's format (precision, flags) when it goes out of
    /// scope, so that the progress lines leave a program's std::cout as
    /// they found it.
    class KeepFormat
    {
    public:
      explicit KeepFormat(std::ostream &out)
        : out(out)
        , saved(nullptr)
      {
        saved.copyfmt(out);
      }
      ~KeepFormat()
      {
        out.copyfmt(saved);
      }

    private:
      std::ostream &out;
      std::ios      saved;
    };
  } // namespace internal

  template <int dim>
  struct Simulator<dim>::Impl : public Drivers::Host
  {
    Impl(const Simulator<dim> &owner, RunSetup<dim> &&setup, MPI_Comm comm);

    // ---- Drivers::Host
    Drivers::SystemInterface &
    system() override
    {
      return *coupled;
    }
    Drivers::DynamicSystemInterface &
    dynamic_system() override
    {
      return *coupled;
    }
    Drivers::SystemInterface::Vector &
    solution() override
    {
      return u;
    }
    /// The inertia check of a nonlinear model with a symmetric tangent.
    Drivers::StabilityInterface *
    stability() override
    {
      const auto &model = coupled->pd_model();
      return !model.linear() && model.symmetric() ? coupled.get() : nullptr;
    }
    /// d r / d t of loads linear in t (CoupledSystem::load_derivative()):
    /// for arc length, and for the Newton driver under hard loading.
    Drivers::NewtonDriver::LoadDerivative
    load_derivative(const bool arc_length) override
    {
      return coupled->load_derivative(!arc_length);
    }
    PDModels::DegradationState
    degradation_state(const double onset_fraction) override
    {
      return coupled->degradation_state(u, onset_fraction);
    }
    void
    report(const std::string &line) override
    {
      if (progress)
        *progress << line << std::endl;
    }
    Drivers::ProgressPulse
    progress_pulse() override
    {
      if (!progress)
        return {};
      return Drivers::ProgressPulse(
        [this](const std::string &line) { report(line); },
        setup.progress_interval);
    }
    void
    after_stability_check(const Drivers::StabilityReport &report) override
    {
      last_check = std::make_unique<Drivers::StabilityReport>(report);
    }
    void
    initial_velocity(Drivers::SystemInterface::Vector &v0) override;
    Drivers::GrowthCheck
    after_equilibrium(const Drivers::StepRecord &record,
                      bool                       allow_growth) override;
    // ---- bonds breaking besides the criterion (simulator_fracture.cc)
    /// Set @p check separated (with its reason) when the grips' secant
    /// stiffness at load factor @p t fell below 1e-3 of its peak.
    void
    separated_by_load(double t, Drivers::GrowthCheck &check);
    /// The state @p u_now was accepted: the PD model records its history
    /// and the bonds it failed break (CoupledSystem::accept_state());
    /// fragments cut loose are then held. Returns the bonds that broke.
    unsigned long
    accept_model_state(const Drivers::SystemInterface::Vector &u_now);
    /// Hold the fragments cut loose (a progress line says how many nodes).
    void
    hold_fragments();
    /// Fracture/Automatic region: FE cells at the stress threshold (and
    /// their margin) become PD, the system is rebuilt with the bonds broken
    /// so far (a progress line says how many cells). Returns whether the
    /// region grew, and else sets @p load_ratio to the load factor ratio
    /// at which the next FE node reaches the threshold.
    bool
    grow_region_by_stress(double &load_ratio);
    /// A new coupled system for setup.cell_is_pd on the same mesh and
    /// DoFs, with the fracture history of the old one replayed.
    void
    rebuild_coupled();
    /// End the run 'separated' (RunFailure) when the bonds the model
    /// failed cut the body into pieces (after the step @p record).
    void
    separated_by_model(const Drivers::StepRecord &record) const;
    bool
    after_time_step(const Drivers::SystemInterface::Vector &u_now,
                    double                                  t) override;
    void
    record_time_step(const Drivers::DynamicRecord &record) override;
    void
    step_boundary(const Drivers::SaveState &save) override;
    /// A history row (and progress line) of the time step @p record.
    void
    write_time_step_row(const Drivers::DynamicRecord &record);
    const StateArchive *
    restart_state() const override
    {
      return restart.get();
    }

    // ---- the run (simulator.cc)
    /// The coupled system, the cracks, the postprocessors, the history.
    void
    set_up();
    /// One history.csv row: the base columns, the criterion's, the
    /// postprocessors' and the wall time.
    void
    add_history_row(const std::vector<double> &base);
    /// Throw RunFailure "interrupted" if a stop signal was @p received (a
    /// signal number from StopOnSignals::stop_requested(), 0: none).
    void
    stop_if_interrupted(int received) const;
    /// Nodal results of the current solution.
    void
    update_results(const Drivers::SystemInterface::Vector &u_now);
    /// Field output through the postprocessors.
    void
    write_fields(double t);

    // ---- checkpoint and restart (simulator_checkpoint.cc)
    /// Check the checkpoint settings against the driver (InputError).
    void
    check_checkpoint_settings() const;
    /// Read this rank's part of the checkpoint to restart from, check it
    /// against the run and take the PD region from it (before the system
    /// is built).
    void
    read_restart();
    /// Take the rest of the state from it (system, cracks, solution,
    /// postprocessors, counters) and continue history.csv (@p columns)
    /// after the rows it had then.
    void
    resume_from_checkpoint(const std::vector<std::string> &columns);
    /// Write a checkpoint of the run, the driver's part from @p save.
    void
    write_checkpoint(const Drivers::SaveState &save);

    // ---- outputs (simulator_output.cc)
    void
    print_header() const;
    /// The progress lines (rank 0; the broken bonds are counted by every
    /// rank before).
    void
    print_static_progress(const Drivers::StepRecord &record,
                          unsigned long              n_broken_bonds) const;
    void
    print_dynamic_progress(const Drivers::DynamicRecord &record,
                           unsigned long                 n_broken_bonds) const;
    /// summary.json with exit state "running" (rank 0), so that a killed
    /// run is never taken for a finished one. Returns why it failed, or "".
    std::string
    write_running_marker() const;
    /// summary.json (rank 0; written to a temporary file and renamed).
    /// Collective. Returns why it failed, or "".
    std::string
    write_summary() const;
    void
    write_summary(std::ostream                &out,
                  const Coupling::ProblemSize &final_size,
                  double                       peak_memory_mb) const;
    void
    print_end() const;

    const Simulator<dim>               &owner;
    RunSetup<dim>                       setup;
    MPI_Comm                            comm;
    bool                                root;
    std::ostream                       *progress = nullptr;
    std::unique_ptr<Drivers::Interface> driver;
    /// The PD model's registry name (Peridynamics/Model, `auto` resolved).
    std::string                                               model_name;
    std::unique_ptr<Fracture::Criterion<dim>>                 criterion;
    std::unique_ptr<Coupling::CoupledSystem<dim>>             coupled;
    std::unique_ptr<Fracture::CrackGrowth<dim>>               cracks;
    std::vector<std::unique_ptr<Postprocess::Interface<dim>>> postprocessors;
    std::unique_ptr<IO::History>                              history;
    dealii::TrilinosWrappers::MPI::Vector                     u;
    std::unique_ptr<Coupling::NodalResults<dim>>              results;
    Fracture::Assessment                                      assessment;
    Drivers::StepRecord                                       step_record;
    /// The last stability check (null: none yet).
    std::unique_ptr<Drivers::StabilityReport> last_check;
    Drivers::DynamicRecord                    time_step_record;
    Coupling::ProblemSize                     initial_size;
    /// The set-up's phases (CoupledSystem::setup_phases() of the first
    /// system; a grown PD region's rebuilds count in the driver's time).
    std::vector<std::pair<std::string, double>> setup_phases;
    double                                      load_factor = 0.;
    unsigned int                                n_steps     = 0;
    /// The solver's changes of path already printed (Type = auto).
    mutable std::size_t printed_solver_switches = 0;
    /// The largest secant stiffness of the grips so far (quasi-static
    /// growth; separated_by_load()).
    double peak_grip_stiffness = 0.;
    /// Dynamic runs: the steps to the end time (once the step is known).
    unsigned int                          n_total_steps = 0;
    std::chrono::steady_clock::time_point run_start;
    /// When the last progress line of a dynamic run was printed.
    mutable std::chrono::steady_clock::time_point last_progress_line;
    double                                        criterion_time = 0.;
    double                                        output_time    = 0.;
    std::string                                   exit_state     = "completed";
    /// The checkpoint restarted from (nullptr: a fresh run).
    std::unique_ptr<StateArchive>         restart;
    unsigned int                          last_checkpoint_step = 0;
    std::chrono::steady_clock::time_point last_checkpoint_time;
    unsigned int                          n_checkpoints = 0;
    /// The step of the last history row.
    unsigned int last_row_step = 0;
    std::string  message;
  };
} // namespace pdfem

#endif
