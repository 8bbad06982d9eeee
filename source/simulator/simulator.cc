// SPDX-License-Identifier: LGPL-2.1-or-later
// The Simulator: one run of any driver, criterion and postprocessors.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/interrupts.h>
#include <pdfem/base/thread_team.h>
#include <pdfem/fracture/automatic_region.h>
#include <pdfem/fracture/crack_growth.h>
#include <pdfem/simulator/summary.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

#include "simulator_impl.h"

namespace pdfem
{
  using namespace dealii;
  using internal::seconds_since;
  using clock = std::chrono::steady_clock;

  template <int dim>
  RunSetup<dim>::RunSetup() = default;
  template <int dim>
  RunSetup<dim>::RunSetup(RunSetup &&) noexcept = default;
  template <int dim>
  RunSetup<dim> &
  RunSetup<dim>::operator=(RunSetup &&) noexcept = default;
  template <int dim>
  RunSetup<dim>::~RunSetup() = default;

  template <int dim>
  parallel::shared::Triangulation<dim> &
  RunSetup<dim>::create_triangulation(MPI_Comm comm)
  {
    tria = std::make_unique<parallel::shared::Triangulation<dim>>(
      comm,
      Triangulation<dim>::none,
      false,
      parallel::shared::Triangulation<dim>::partition_metis);
    return *tria;
  }

  // ------------------------------------------------------------------ Impl
  template <int dim>
  Simulator<dim>::Impl::Impl(const Simulator<dim> &owner,
                             RunSetup<dim>       &&setup_in,
                             MPI_Comm              comm)
    : owner(owner)
    , setup(std::move(setup_in))
    , comm(comm)
    , root(Utilities::MPI::this_mpi_process(comm) == 0)
    , progress(root ? &std::cout : nullptr)
  {}

  namespace
  {
    /// Remove the run outputs pdfem writes (and only those) from @p folder;
    /// parameters.prm, written for this run before, and other files stay.
    void
    remove_earlier_outputs(const std::string &folder)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      for (const auto &entry : fs::directory_iterator(folder, ec))
        {
          const std::string name  = entry.path().filename().string();
          const bool        field = name.rfind("solution_", 0) == 0 &&
                             (entry.path().extension() == ".vtu" ||
                              entry.path().extension() == ".pvtu");
          if (entry.is_regular_file() &&
              (field || name == "history.csv" || name == "summary.json" ||
               name == "summary.json.tmp" || name == "nodes.csv" ||
               name == "solution.pvd" || name == "crack_paths.vtk" ||
               name == "crack_paths.csv"))
            fs::remove(entry.path(), ec);
        }
    }
  } // namespace

  template <int dim>
  void
  Simulator<dim>::Impl::set_up()
  {
    const std::string threads_note = fit_threads_to_cores();
    if (root)
      for (const auto &notes : {setup.notes,
                                driver->notes(),
                                std::vector<std::string>{threads_note}})
        for (const auto &note : notes)
          if (!note.empty())
            std::cerr << "pdfem: note: " << note << std::endl;

    auto &tria = *setup.tria;
    if (!setup.restart_from.empty())
      read_restart(); // the PD region as it had grown
    if (setup.cell_is_pd.empty())
      setup.cell_is_pd.assign(tria.n_active_cells(), false);
    // A scene may start with PD only around its cracks.
    Fracture::extend_pd_region(tria,
                               setup.settings.cracks,
                               setup.fracture.adaptive_margin,
                               setup.cell_is_pd);
    coupled      = std::make_unique<Coupling::CoupledSystem<dim>>(tria,
                                                             setup.cell_is_pd,
                                                             setup.settings);
    initial_size = coupled->size();
    setup_phases = coupled->setup_phases();
    // A static solve needs every piece of the body held against rigid
    // motion (a dynamic one does not: the mass holds it).
    if (!driver->dynamic())
      {
        const auto unheld = coupled->unheld_rigid_motions();
        if (!unheld.empty())
          throw InputError(
            setup.file,
            "Boundary conditions/Dirichlet",
            unheld[0] +
              (unheld.size() > 1 ?
                 " (and " + std::to_string(unheld.size() - 1) + " more)" :
                 ""),
            "prescribed displacements that hold every piece against each "
            "rigid motion (" +
              std::to_string(dim * (dim + 1) / 2) +
              ": translations and rotations)");
        const std::string unheld_component = coupled->unheld_component();
        if (!unheld_component.empty())
          throw InputError(setup.file,
                           "Boundary conditions/Dirichlet",
                           unheld_component,
                           "that component prescribed at every PD node, e.g. "
                           "on boundaries that together hold every node (a "
                           "uniaxial bar: y = 0 on bottom and top)");
      }
    setup.timings["setup"] = seconds_since(setup.setup_start);
    print_header();

    if (criterion)
      cracks = std::make_unique<Fracture::CrackGrowth<dim>>(
        setup.fracture,
        setup.settings.material,
        setup.settings.cracks,
        *coupled,
        setup.tip_at_end,
        dim == 3 && criterion->tracks_tips());
    coupled->initialize_vector(u);

    // Every registered postprocessor, then the program's own, each taking
    // part where it says so.
    std::vector<std::unique_ptr<Postprocess::Interface<dim>>> offered;
    for (const auto &name : Postprocess::registry<dim>().names())
      offered.push_back(Postprocess::registry<dim>().create(name));
    for (auto &p : postprocessors)
      offered.push_back(std::move(p));
    postprocessors.clear();
    for (auto &p : offered)
      {
        p->initialize_simulator(owner);
        if (p->initialize())
          postprocessors.push_back(std::move(p));
      }

    std::vector<std::string> columns = Summary::first_history_columns();
    for (const auto &c : driver->history_columns())
      columns.push_back(c);
    if (criterion)
      for (const auto &c : criterion->history_columns(*cracks))
        columns.push_back(c);
    for (const auto &p : postprocessors)
      for (const auto &c : p->history_columns())
        columns.push_back(c);
    columns.push_back("wall_seconds");
    last_checkpoint_time = clock::now();
    if (restart)
      resume_from_checkpoint(columns);
    // From here on the run writes: the outputs an earlier run left in the
    // folder go first (so that none is taken for this run's; a restart
    // keeps them: it continues that run), and a killed run leaves
    // summary.json saying it did not end.
    if (root && !restart)
      remove_earlier_outputs(setup.out_dir);
    const std::string marker_error =
      Utilities::MPI::broadcast(comm, write_running_marker(), 0);
    if (!marker_error.empty())
      throw InputError(setup.file,
                       "Output/Directory",
                       marker_error,
                       "a writable folder with free space");

    if (!restart)
      history = std::make_unique<IO::History>(setup.out_dir + "/history.csv",
                                              columns,
                                              root);
  }

  template <int dim>
  void
  Simulator<dim>::Impl::add_history_row(const std::vector<double> &base)
  {
    std::vector<double> row = base;
    driver->history_values(row);
    if (criterion)
      criterion->history_values(*cracks, assessment, row);
    for (const auto &p : postprocessors)
      p->history_values(row);
    row.push_back(seconds_since(setup.total_start));
    last_row_step = static_cast<unsigned int>(base[0]);
    // No NaN is written: a non-finite value ends the run (the same on
    // every rank: the row's values are global).
    for (std::size_t c = 0; c < row.size(); ++c)
      if (!std::isfinite(row[c]))
        throw RunFailure("diverged",
                         "history.csv column '" + history->column(c) +
                           "' is not finite (NaN or Inf) at step " +
                           number(row[0]) +
                           ": check the loads, the initial velocity and the "
                           "time step");
    // Rank 0 writes; every rank learns whether it could.
    const int written = history->add_row(row) ? 1 : 0;
    if (Utilities::MPI::min(written, comm) == 0)
      throw RunFailure("io error",
                       "writing " + setup.out_dir +
                         "/history.csv failed (disk full, or the folder no "
                         "longer writable)");
  }

  template <int dim>
  void
  Simulator<dim>::Impl::update_results(
    const Drivers::SystemInterface::Vector &u_now)
  {
    results = std::make_unique<Coupling::NodalResults<dim>>(
      coupled->nodal_results(u_now));
  }

  template <int dim>
  void
  Simulator<dim>::Impl::write_fields(const double t)
  {
    const auto start = clock::now();
    for (const auto &p : postprocessors)
      p->write_fields(t);
    output_time += seconds_since(start);
  }

  // ------------------------------------------------------- Drivers::Host
  template <int dim>
  void
  Simulator<dim>::Impl::initial_velocity(Drivers::SystemInterface::Vector &v0)
  {
    coupled->interpolate(setup.driver.initial_velocity,
                         "Driver/Initial velocity",
                         v0);
  }

  template <int dim>
  Drivers::GrowthCheck
  Simulator<dim>::Impl::after_equilibrium(const Drivers::StepRecord &record,
                                          const bool allow_growth)
  {
    const auto          start    = clock::now();
    const unsigned long degraded = accept_model_state(u);
    step_record                  = record;
    n_steps                      = record.step;
    load_factor                  = record.load_factor;
    const unsigned int planned   = driver->planned_steps();
    const bool         fields_due =
      setup.write_every > 0 && record.step % setup.write_every == 0 &&
      (planned > 0 ? record.step < planned : record.load_factor < 1. - 1e-12);
    // Nodal results: now if the criterion or the fields need them, else
    // on a postprocessor's demand (get_nodal_results()).
    results.reset();
    if (cracks || fields_due)
      update_results(u);
    assessment = Fracture::Assessment();
    if (cracks)
      {
        assessment =
          criterion->evaluate(*cracks, *coupled, *results, allow_growth);
        Fracture::CrackGrowth<dim>::count_pieces(assessment,
                                                 *coupled,
                                                 *results);
      }
    criterion_time += seconds_since(start);

    const Coupling::ProblemSize s = coupled->size();
    add_history_row({double(record.step),
                     record.time,
                     record.load_factor,
                     double(record.newton_iterations),
                     double(record.linear_iterations),
                     record.relative_residual,
                     double(s.n_broken_bonds),
                     coupled->max_damage()});
    print_static_progress(record, s.n_broken_bonds);
    if (fields_due)
      write_fields(record.time);

    // Fracture/Automatic region: FE cells at the threshold become PD (this
    // step's row and fields are the old region's) and the step is solved
    // again at the same load.
    double     region_ratio = std::numeric_limits<double>::infinity();
    const bool region_grew  = setup.fracture.automatic_region > 0. &&
                             allow_growth &&
                             grow_region_by_stress(region_ratio);
    Drivers::GrowthCheck check;
    check.grew = assessment.broken_bonds > 0 || region_grew;
    check.critical_load_ratio =
      Fracture::capped_load_ratio(assessment.critical_load_ratio, region_ratio);
    check.separated = assessment.pieces > 1;
    if (cracks && allow_growth && !check.separated && !region_grew)
      separated_by_load(record.load_factor, check);
    // The PD region follows the cracks: a new system on the same mesh and
    // DoFs, with every crack so far cut.
    if (check.grew && cracks &&
        Fracture::extend_pd_region(*setup.tria,
                                   cracks->segments(),
                                   setup.fracture.adaptive_margin,
                                   setup.cell_is_pd) > 0)
      rebuild_coupled();
    if (check.grew)
      hold_fragments();
    if (degraded > 0 && !cracks)
      separated_by_model(record);
    // A resumable driver stops at its next step boundary, after a
    // checkpoint (step_boundary()).
    if (!driver->resumable())
      stop_if_interrupted(StopOnSignals::stop_requested(comm));
    return check;
  }

  template <int dim>
  void
  Simulator<dim>::Impl::stop_if_interrupted(const int received) const
  {
    if (received != 0)
      throw RunFailure("interrupted",
                       std::string(StopOnSignals::name(received)) +
                         " received: stopped after step " +
                         std::to_string(n_steps) + " (load factor " +
                         number(load_factor) + "), the state the outputs hold");
  }

  template <int dim>
  bool
  Simulator<dim>::Impl::after_time_step(
    const Drivers::SystemInterface::Vector &u_now,
    double)
  {
    results.reset();
    const bool degraded = accept_model_state(u_now) > 0;
    if (!cracks)
      return degraded;
    const auto start = clock::now();
    update_results(u_now);
    assessment = criterion->evaluate(*cracks, *coupled, *results, true);
    Fracture::CrackGrowth<dim>::count_pieces(assessment, *coupled, *results);
    criterion_time += seconds_since(start);
    return degraded || assessment.broken_bonds > 0;
  }

  template <int dim>
  void
  Simulator<dim>::Impl::record_time_step(const Drivers::DynamicRecord &record)
  {
    const auto &prm  = setup.driver;
    time_step_record = record;
    n_steps          = record.step;
    load_factor      = record.time / prm.end_time;
    if (n_total_steps == 0 && record.time_step > 0.)
      n_total_steps = static_cast<unsigned int>(
        std::ceil(prm.end_time / record.time_step - 1e-9));
    if (record.step == 0)
      run_start = clock::now();
    if (record.step == 0 && progress)
      {
        const internal::KeepFormat keep(*progress);
        *progress << "  time step " << record.time_step << " s"
                  << driver->first_step_note(record) << "; " << n_total_steps
                  << " steps to t = " << prm.end_time << " s" << std::endl;
      }
    for (const auto &p : postprocessors)
      p->every_time_step();
    if (!std::isfinite(record.kinetic_energy) ||
        !std::isfinite(record.strain_energy) ||
        !std::isfinite(record.external_work))
      throw RunFailure("diverged",
                       "the state is not finite (NaN or Inf) at step " +
                         std::to_string(record.step) +
                         ", t = " + number(record.time) +
                         " s: check the loads, the initial velocity and the "
                         "time step");
    // An interrupted run records the step it stops at.
    const int stop =
      driver->resumable() ? 0 : StopOnSignals::stop_requested(comm);
    const bool last_step = record.step >= n_total_steps || stop != 0;
    if (record.step % prm.history_interval != 0 && !last_step &&
        !(record.energy_error > prm.energy_tolerance) &&
        std::isfinite(record.energy_error))
      return;
    write_time_step_row(record);
    stop_if_interrupted(stop);
  }

  // ------------------------------------------------------------ Simulator
  template <int dim>
  Simulator<dim>::Simulator(RunSetup<dim> &&setup,
                            MPI_Comm        comm,
                            RunPlugins<dim> plugins)
    : impl(std::make_unique<Impl>(*this, std::move(setup), comm))
  {
    Impl &s = *impl;
    if (!s.setup.tria)
      throw InputError(s.setup.file, "", "the run has no mesh");
    if (s.setup.total_start == clock::time_point())
      s.setup.total_start = clock::now();
    if (s.setup.setup_start == clock::time_point())
      s.setup.setup_start = clock::now();
    if (s.setup.out_dir.empty())
      s.setup.out_dir =
        "output-" + (s.setup.name.empty() ? std::string("run") : s.setup.name);
    // The output folder (rank 0), before any work.
    std::string folder_error;
    if (s.root)
      {
        std::error_code ec;
        std::filesystem::create_directories(s.setup.out_dir, ec);
        if (ec || !std::filesystem::is_directory(s.setup.out_dir))
          folder_error = "cannot create the output folder '" + s.setup.out_dir +
                         "': " + ec.message();
      }
    folder_error = Utilities::MPI::broadcast(comm, folder_error, 0);
    if (!folder_error.empty())
      throw InputError(s.setup.file,
                       "Output/Directory",
                       folder_error,
                       "a writable folder");
    if (!plugins.driver)
      plugins = make_plugins<dim>(s.setup.file,
                                  s.setup.driver,
                                  s.setup.fracture,
                                  ModelChoice{"pdlsm"},
                                  nullptr,
                                  s.setup.settings.material.density,
                                  s.setup.settings.linear_solver);
    if (plugins.model)
      s.setup.settings.pd_model = plugins.model;
    // Linear solver Type = auto made concrete for this model and driver.
    s.setup.settings.linear_solver =
      resolve_linear_solver(s.setup.settings.linear_solver,
                            plugins.model.get(),
                            *plugins.driver);
    s.setup.settings.prepare_solver = plugins.driver->solves_linear_systems();
    s.model_name                    = plugins.model_name;
    s.driver                        = std::move(plugins.driver);
    s.criterion                     = std::move(plugins.criterion);
    // The driver's validated parameters (time step, monitor points parsed)
    // are the run's.
    s.setup.driver = s.driver->settings();
    s.check_checkpoint_settings();
  }

  template <int dim>
  Simulator<dim>::~Simulator() = default;

  template <int dim>
  void
  Simulator<dim>::add_postprocessor(
    std::unique_ptr<Postprocess::Interface<dim>> p)
  {
    impl->postprocessors.push_back(std::move(p));
  }

  template <int dim>
  void
  Simulator<dim>::set_quiet(const bool quiet)
  {
    impl->progress = (impl->root && !quiet) ? &std::cout : nullptr;
  }

  template <int dim>
  int
  Simulator<dim>::run()
  {
    Impl &s = *impl;
    // SIGINT/SIGTERM end the run after the current step, outputs written.
    const StopOnSignals stop_on_signals;
    s.set_up();
    s.run_start = clock::now();
    try
      {
        s.driver->run(s);
      }
    catch (const RunFailure &e)
      {
        s.exit_state = e.exit_state;
        s.message    = e.what();
        if (s.root)
          std::cerr << "pdfem: run "
                    << (s.exit_state == "separated" ? "ended" : "stopped")
                    << ": " << s.message << std::endl;
      }
    for (const auto &[phase, seconds] : s.driver->timings())
      s.setup.timings[phase] = seconds;
    s.setup.timings["criterion"] = s.criterion_time;

    // ---- results at the last state
    const auto start = clock::now();
    if (s.driver->dynamic() && !s.coupled->reaction_names().empty())
      {
        TrilinosWrappers::MPI::Vector r;
        s.coupled->residual(s.u, s.time_step_record.time, r, false);
      }
    s.update_results(s.u);
    try
      {
        s.write_fields(s.driver->dynamic() ? s.time_step_record.time :
                                             s.step_record.time);
        for (const auto &p : s.postprocessors)
          p->finish();
      }
    catch (const RunFailure &e)
      {
        // An output that could not be written: the run's own end state
        // stays if it had already stopped for another reason.
        if (s.exit_state == "completed" || s.exit_state == "separated")
          {
            s.exit_state = e.exit_state;
            s.message    = e.what();
          }
        if (s.root)
          std::cerr << "pdfem: " << e.what() << std::endl;
      }
    s.output_time += seconds_since(start);
    s.setup.timings["output"]       = s.output_time;
    s.setup.timings["total"]        = seconds_since(s.setup.total_start);
    const std::string summary_error = s.write_summary();
    s.print_end();
    if (!summary_error.empty())
      {
        std::cerr << "pdfem: error: summary.json: " << summary_error
                  << std::endl;
        return 3;
      }
    return s.exit_state == "completed" || s.exit_state == "separated" ? 0 : 3;
  }

  // ------------------------------------------------------- read access
  template <int dim>
  MPI_Comm
  Simulator<dim>::get_mpi_communicator() const
  {
    return impl->comm;
  }

  template <int dim>
  const RunSetup<dim> &
  Simulator<dim>::get_setup() const
  {
    return impl->setup;
  }

  template <int dim>
  const Coupling::CoupledSystem<dim> &
  Simulator<dim>::get_system() const
  {
    return *impl->coupled;
  }

  template <int dim>
  Coupling::CoupledSystem<dim> &
  Simulator<dim>::get_mutable_system() const
  {
    return *impl->coupled;
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  Simulator<dim>::get_solution() const
  {
    return impl->u;
  }

  template <int dim>
  const Coupling::NodalResults<dim> &
  Simulator<dim>::get_nodal_results() const
  {
    if (!impl->results)
      impl->update_results(impl->u);
    return *impl->results;
  }

  template <int dim>
  const Drivers::Interface &
  Simulator<dim>::get_driver() const
  {
    return *impl->driver;
  }

  template <int dim>
  const Drivers::StepRecord &
  Simulator<dim>::get_step_record() const
  {
    return impl->step_record;
  }

  template <int dim>
  const Drivers::DynamicRecord &
  Simulator<dim>::get_time_step_record() const
  {
    return impl->time_step_record;
  }

  template <int dim>
  double
  Simulator<dim>::get_load_factor() const
  {
    return impl->load_factor;
  }

  template <int dim>
  const Drivers::StabilityReport *
  Simulator<dim>::get_last_stability_check() const
  {
    return impl->last_check.get();
  }

  template <int dim>
  std::ostream *
  Simulator<dim>::get_progress_stream() const
  {
    return impl->progress;
  }

  template <int dim>
  const Fracture::CrackGrowth<dim> *
  Simulator<dim>::get_cracks() const
  {
    return impl->cracks.get();
  }

  template <int dim>
  const Fracture::Criterion<dim> *
  Simulator<dim>::get_criterion() const
  {
    return impl->criterion.get();
  }

  template <int dim>
  const Fracture::Assessment &
  Simulator<dim>::get_assessment() const
  {
    return impl->assessment;
  }

#define INSTANTIATE(dim)         \
  template struct RunSetup<dim>; \
  template class Simulator<dim>;
  PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace pdfem
