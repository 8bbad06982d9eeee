// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SIMULATOR_SIMULATOR_H
#define PDFEM_SIMULATOR_SIMULATOR_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/fracture/criterion.h>
#include <pdfem/pd_models/interface.h>

#include <chrono>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <mpi.h>

namespace pdfem
{
  namespace Postprocess
  {
    template <int dim>
    class Interface;
  }

  /**
   * What one run is made of, whatever it was read from (a `.prm` scene, a
   * PDLSM-FEM command file) or written by (a program against the library):
   * the mesh and which cells are PD, the coupled system's settings
   * (material, PD discretisation, boundary conditions, linear solver), the
   * driver's and the criterion's parameters (whose `type` and `criterion`
   * name the plugins), and the outputs.
   */
  template <int dim>
  struct RunSetup
  {
    RunSetup();
    RunSetup(RunSetup &&) noexcept;
    RunSetup &
    operator=(RunSetup &&) noexcept;
    ~RunSetup();

    /// Make @p tria an empty mesh shared by the ranks of @p comm and
    /// partitioned by METIS (how every pdfem run holds its mesh), to be
    /// filled by Mesh::read_msh() or a deal.II GridGenerator; returns it.
    dealii::parallel::shared::Triangulation<dim, dim> &
    create_triangulation(MPI_Comm comm);

    /// The input file (messages, summary.json) and its stem.
    std::string file;
    std::string name;
    /// The output folder (created by the Simulator if missing).
    std::string out_dir;
    /// The mesh, partitioned among the ranks (Mesh::read_msh() or any
    /// deal.II GridGenerator).
    std::unique_ptr<dealii::parallel::shared::Triangulation<dim, dim>> tria;
    /// Which active cells are PD (by active cell index); empty: none.
    std::vector<bool>       cell_is_pd;
    Coupling::Settings<dim> settings;
    /// `Driver/Type` names the driver plugin.
    Drivers::Settings driver;
    /// `Fracture/Criterion` names the criterion plugin ("none": none).
    Fracture::Settings fracture;
    /// Which end of each initial crack is its tip (empty: every end inside
    /// the body that touches no other crack).
    std::vector<bool> tip_at_end;
    bool              write_vtu = true;
    /// Field output every this many steps (and at the last); 0: last.
    unsigned int write_every     = 0;
    bool         write_nodes_csv = false;
    bool         print_timings   = false;
    /// The coupling's patch test before the run: "auto" (pairwise PD
    /// models with FE cells), "true" or "false".
    std::string patch_test = "auto";
    /// Checkpoints (doc/reliability.md): every this many steps (0: not by
    /// count) and every this many minutes of wall time (0: not by time);
    /// SIGINT and SIGTERM write one too. Drivers that can resume only
    /// (Drivers::Interface::resumable()).
    unsigned int checkpoint_steps   = 0;
    double       checkpoint_minutes = 0.;
    /// A progress line at least every this many seconds inside long steps
    /// and between the lines of a dynamic run (Drivers::ProgressPulse).
    double progress_interval = 5.;
    /// Go on from the checkpoint in this folder (the output folder of the
    /// interrupted run, or its `checkpoint` folder); empty: a fresh run.
    std::string restart_from;
    /// Dirichlet sets whose reactions are also summed as "RF".
    std::vector<unsigned int> reaction_group;
    /// Remarks printed on stderr before the run.
    std::vector<std::string> notes;
    /// Wall seconds of what was done before the Simulator ("mesh").
    std::map<std::string, double>         timings;
    std::chrono::steady_clock::time_point total_start;
    std::chrono::steady_clock::time_point setup_start;
  };

  /**
   * What the driver and criterion check of a run: @p model_name and
   * whether it is @p nonlinear, the @p density (a mass exists), the linear
   * solver (whether it assembles the coupled matrix), whether the model
   * degrades smoothly and gives its tangent row by row.
   */
  Drivers::RunTraits
  make_run_traits(const std::string       &file,
                  int                      dim,
                  const std::string       &model_name,
                  bool                     nonlinear,
                  double                   density,
                  const Solvers::Settings &linear_solver,
                  const std::string       &driver_name,
                  bool                     smooth_degradation = false,
                  bool                     tangent_rows       = false);

  /**
   * @p linear_solver with Type = auto made concrete for the PD model @p
   * model (nullptr: the collocated pdlsm) and @p driver
   * (Solvers::Settings::resolve()).
   */
  template <int dim>
  Solvers::Settings
  resolve_linear_solver(const Solvers::Settings        &linear_solver,
                        const PDModels::Interface<dim> *model,
                        const Drivers::Interface       &driver);

  /**
   * Check that @p driver, @p criterion (nullptr: none) and the rest of the
   * run described by @p traits and @p fracture fit together: each plugin's
   * own check(), then what concerns them together. Throws InputError.
   */
  template <int dim>
  void
  check_plugins(const Drivers::Interface       &driver,
                const Fracture::Criterion<dim> *criterion,
                const Drivers::RunTraits       &traits,
                const Fracture::Settings       &fracture);

  /**
   * The PD model, driver and criterion (nullptr: none) of a run. A null
   * model is PDLSM collocation with Coupling::Settings::weight_factor.
   */
  template <int dim>
  struct RunPlugins
  {
    std::shared_ptr<PDModels::Interface<dim>> model;
    /// The model's registry name, `auto` resolved (default_model_name()).
    std::string                               model_name = "pdlsm";
    std::unique_ptr<Drivers::Interface>       driver;
    std::unique_ptr<Fracture::Criterion<dim>> criterion;
  };

  /**
   * The PD model a scene asks for: a registry name or `auto`, with what
   * `auto` is resolved from (default_model_name()).
   */
  struct ModelChoice
  {
    std::string name = "auto";
    /// The scene starts with cracks (Peridynamics/Pre-existing cracks).
    bool pre_existing_cracks = false;
    /// Peridynamics/Crack faces = free surface, an option of `pdlsm`.
    bool free_crack_faces = false;
  };

  /**
   * The PD model that `Peridynamics/Model = auto` stands for, picked from
   * the measurements of doc/benchmarks/operator.md and dynamics.md
   * (issue 16):
   * - the energy form `pdlsm energy` for dynamic drivers (the collocated
   *   pdlsm's stiffness is not symmetric, and M^-1 K has growing modes)
   *   and for scenes with cracks, pre-existing or grown by a criterion
   *   (its supports carry nothing, so K does not depend on where the body
   *   is held, and its K converges with the mesh);
   * - the collocated `pdlsm` (PDLSM-FEM's operator) for crack-free static
   *   scenes (more accurate per second on a stress concentration), and
   *   for static scenes that ask for `Crack faces = free surface`, an
   *   option of the collocated operator only.
   */
  std::string
  default_model_name(bool dynamic_driver, bool cracks, bool free_crack_faces);

  /**
   * The PD model of @p model (`auto`: default_model_name() for the
   * driver, the cracks and the criterion), the driver and the criterion named
   * in
   * @p driver_settings (`type`) and @p fracture (`criterion`), made from
   * the registries, given their parameters and checked together with the
   * rest of the run (make_run_traits(), check_plugins()). The model reads
   * its own parameters from @p parameters (a parameter file as read; if
   * nullptr, no model is made: PDLSM collocation with the settings'
   * weight factor). Throws InputError: a scene calls it before reading its
   * mesh, so that bad input stops before any work.
   */
  template <int dim>
  RunPlugins<dim>
  make_plugins(const std::string        &file,
               const Drivers::Settings  &driver_settings,
               const Fracture::Settings &fracture,
               const ModelChoice        &model,
               dealii::ParameterHandler *parameters,
               double                    density,
               const Solvers::Settings  &linear_solver);

  /**
   * The output folder that the checkpoint @p restart_path (an output
   * folder, or the `checkpoint` folder in one) belongs to. InputError if
   * there is no checkpoint there.
   */
  std::string
  checkpoint_output_folder(const std::string &restart_path);

  /**
   * One run of the coupled PD-FE method (in the spirit of ASPECT's
   * Simulator): it owns the mesh and regions, the coupled system, the
   * driver, the crack criterion and the postprocessors, runs the driver
   * and writes history.csv, summary.json and the fields. Plugins and
   * programs read its state through SimulatorAccess.
   *
   * The data flow of a run: set-up (mesh, regions, settings) → coupled
   * system (FE cell, PD and boundary terms) → driver (solves through the
   * Drivers::Host the Simulator implements) → criterion (after each
   * converged state) → postprocessors (history columns, summary members,
   * files).
   *
   * Bad input throws InputError from the constructor, before any work; a
   * failure during run() (RunFailure) becomes the exit state in
   * summary.json.
   */
  template <int dim>
  class Simulator
  {
  public:
    /**
     * A run of @p setup on @p comm with @p plugins as make_plugins() gives
     * them (made, given their parameters and checked); without a driver,
     * make_plugins() is called here with the names in the set-up (the
     * PDLSM model). Throws InputError.
     */
    Simulator(RunSetup<dim> &&setup,
              MPI_Comm        comm,
              RunPlugins<dim> plugins = {});
    ~Simulator();

    /// Add a postprocessor (besides every registered one).
    void
    add_postprocessor(std::unique_ptr<Postprocess::Interface<dim>> p);

    /// No progress lines on the terminal.
    void
    set_quiet(bool quiet);

    /**
     * Run: build the coupled system, run the driver, write every output.
     * Returns 0 when the run completed (or the body separated), 3 when it
     * stopped (the reason is summary.json's exit state).
     */
    int
    run();

    /// @name Read access (see SimulatorAccess)
    /// @{
    MPI_Comm
    get_mpi_communicator() const;
    const RunSetup<dim> &
    get_setup() const;
    const Coupling::CoupledSystem<dim> &
    get_system() const;
    /// The system, for postprocessors that update its caches (reactions,
    /// lumped mass); they must not change the state it solves for.
    Coupling::CoupledSystem<dim> &
    get_mutable_system() const;
    const dealii::TrilinosWrappers::MPI::Vector &
    get_solution() const;
    const Coupling::NodalResults<dim> &
    get_nodal_results() const;
    const Drivers::Interface &
    get_driver() const;
    const Drivers::StepRecord &
    get_step_record() const;
    const Drivers::DynamicRecord &
    get_time_step_record() const;
    double
    get_load_factor() const;
    const Drivers::StabilityReport *
    get_last_stability_check() const;
    std::ostream *
    get_progress_stream() const;
    const Fracture::CrackGrowth<dim> *
    get_cracks() const;
    const Fracture::Criterion<dim> *
    get_criterion() const;
    const Fracture::Assessment &
    get_assessment() const;
    /// @}

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };

  /**
   * Read access to a running Simulator for plugins and programs (ASPECT's
   * SimulatorAccess): the mesh, the system, the solution and nodal
   * results, the step, the cracks and the output folder.
   */
  template <int dim>
  class SimulatorAccess
  {
  public:
    virtual ~SimulatorAccess() = default;

    /// Called by the Simulator before the plugin is used.
    void
    initialize_simulator(const Simulator<dim> &simulator);

    const Simulator<dim> &
    get_simulator() const;
    MPI_Comm
    get_mpi_communicator() const;
    /// Is this rank 0 (the one that writes files)?
    bool
    is_root() const;
    const RunSetup<dim> &
    get_setup() const;
    const dealii::parallel::shared::Triangulation<dim, dim> &
    get_triangulation() const;
    const Coupling::CoupledSystem<dim> &
    get_system() const;
    /// See Simulator::get_mutable_system().
    Coupling::CoupledSystem<dim> &
    get_mutable_system() const;
    const dealii::TrilinosWrappers::MPI::Vector &
    get_solution() const;
    /// Displacement, stress and damage per node at the last state (computed
    /// once per step, when a criterion or an output needs them).
    const Coupling::NodalResults<dim> &
    get_nodal_results() const;
    const Drivers::Interface &
    get_driver() const;
    /// Is the run integrating in time?
    bool
    is_dynamic() const;
    const Drivers::StepRecord &
    get_step_record() const;
    const Drivers::DynamicRecord &
    get_time_step_record() const;
    /// The load factor t (dynamic runs: time / end time).
    double
    get_load_factor() const;
    /// The last stability check of the Newton or arc-length driver
    /// (nullptr: none yet, or none in this run).
    const Drivers::StabilityReport *
    get_last_stability_check() const;
    /// Where progress lines go (nullptr: nowhere, quiet or not rank 0).
    std::ostream *
    get_progress_stream() const;
    /// The cracks (nullptr without a criterion).
    const Fracture::CrackGrowth<dim> *
    get_cracks() const;
    const Fracture::Assessment &
    get_assessment() const;
    const std::string &
    get_output_directory() const;

  private:
    const Simulator<dim> *simulator = nullptr;
  };
} // namespace pdfem

#endif
