// SPDX-License-Identifier: LGPL-2.1-or-later
// The part of a run that is the same whatever the input format: the coupled
// system, the driver, the crack criterion and every output.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/drivers/quasi_static_driver.h>
#include <pdfem/drivers/static_driver.h>
#include <pdfem/fracture/crack_growth.h>
#include <pdfem/io/field_output.h>
#include <pdfem/io/history.h>
#include <pdfem/io/json_writer.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>

#include "scene_internal.h"
#include <sys/resource.h>

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      using namespace dealii;
      using Coupling::component_names;
      using Coupling::stress_component;
      using Coupling::stress_component_names;

      namespace
      {
        using clock = std::chrono::steady_clock;

        /// The reaction (component) of largest magnitude seen, and when.
        struct Peak
        {
          double       value = 0.;
          unsigned int step  = 0;
          double       load  = 0.;
          void
          update(const double v, const unsigned int s, const double t)
          {
            if (std::abs(v) > std::abs(value) || step == 0)
              {
                value = v;
                step  = s;
                load  = t;
              }
          }
        };
      } // namespace

      template <int dim>
      std::vector<std::string>
      base_history_columns(const std::vector<std::string> &reaction_sets,
                           const bool                      reaction_group)
      {
        std::vector<std::string> columns = {"step",
                                            "time",
                                            "load_factor",
                                            "newton_iterations",
                                            "linear_iterations",
                                            "residual",
                                            "n_broken_bonds",
                                            "max_damage"};
        for (const auto &set : reaction_sets)
          for (const auto &c : component_names<dim>())
            columns.push_back("reaction_" + IO::History::column_name(set) +
                              "_" + c);
        if (reaction_group)
          for (const auto &c : component_names<dim>())
            columns.push_back("reaction_RF_" + c);
        return columns;
      }

      template <int dim>
      void
      write_final_fields(IO::JsonWriter                    &json,
                         const Coupling::NodalResults<dim> &results)
      {
        const auto          comps  = component_names<dim>();
        const auto          scomps = stress_component_names<dim>();
        const double        inf    = std::numeric_limits<double>::infinity();
        std::vector<double> umax(dim, -inf), umin(dim, inf),
          smax(scomps.size(), -inf), smin(scomps.size(), inf);
        double s1max = -inf, dmax = 0.;
        for (unsigned int k = 0; k < results.position.size(); ++k)
          {
            for (unsigned int c = 0; c < dim; ++c)
              {
                umax[c] = std::max(umax[c], results.displacement[k][c]);
                umin[c] = std::min(umin[c], results.displacement[k][c]);
              }
            for (unsigned int c = 0; c < scomps.size(); ++c)
              {
                const double v = stress_component(results.stress[k], c);
                smax[c]        = std::max(smax[c], v);
                smin[c]        = std::min(smin[c], v);
              }
            s1max = std::max(s1max, eigenvalues(results.stress[k])[0]);
            dmax  = std::max(dmax, results.damage[k]);
          }
        const auto object = [&](const char                     *name,
                                const std::vector<std::string> &keys,
                                const std::vector<double>      &values) {
          json.begin_object(name);
          for (unsigned int c = 0; c < keys.size(); ++c)
            json.value(keys[c], values[c]);
          json.end_object();
        };
        object("max_displacement", comps, umax);
        object("min_displacement", comps, umin);
        object("max_stress", scomps, smax);
        object("min_stress", scomps, smin);
        json.value("max_principal_stress", s1max);
        json.value("max_damage", dmax);
      }

      template <int dim>
      void
      write_final_reactions(
        IO::JsonWriter                            &json,
        const std::vector<std::string>            &names,
        const std::vector<dealii::Tensor<1, dim>> &reactions,
        const std::vector<unsigned int>           &group)
      {
        const auto comps = component_names<dim>();
        json.begin_object("reaction");
        for (std::size_t s = 0; s < names.size(); ++s)
          {
            json.begin_object(names[s]);
            for (unsigned int c = 0; c < dim; ++c)
              json.value(comps[c], reactions[s][c]);
            json.end_object();
          }
        json.end_object();
        if (!group.empty())
          {
            const auto R = group_reaction(reactions, group);
            json.begin_object("reaction_RF");
            for (unsigned int c = 0; c < dim; ++c)
              json.value(comps[c], R[c]);
            json.end_object();
          }
      }

      template <int dim>
      void
      write_summary_header(IO::JsonWriter              &json,
                           const Setup<dim>            &setup,
                           MPI_Comm                     comm,
                           const std::string           &exit_state,
                           const std::string           &message,
                           const Coupling::ProblemSize &size,
                           const Coupling::ProblemSize &final_size)
      {
        json.value("pdfem_version", PDFEM_VERSION);
        json.value("scene", setup.name);
        json.value("input_file", setup.file);
        json.value("dimension", static_cast<unsigned long>(dim));
        json.value("ranks",
                   static_cast<unsigned long>(
                     Utilities::MPI::n_mpi_processes(comm)));
        json.value("threads",
                   static_cast<unsigned long>(MultithreadInfo::n_threads()));
        json.value("exit_state", exit_state);
        json.value("message", message);
        json.begin_object("problem");
        json.value("nodes", size.n_nodes);
        json.value("pd_nodes", size.n_pd_nodes);
        json.value("interface_nodes", size.n_interface_nodes);
        json.value("cells", size.n_cells);
        json.value("pd_cells", size.n_pd_cells);
        json.value("dofs", size.n_dofs);
        json.value("bonds", size.n_bonds);
        json.value("broken_bonds", final_size.n_broken_bonds);
        json.value("decoupled_nodes", final_size.n_decoupled_nodes);
        json.value("pd_boundary_faces", size.n_pd_boundary_faces);
        json.value("matrix_entries_rank0", size.n_matrix_entries);
        json.end_object();
      }

      template <int dim>
      int
      execute(Setup<dim> &setup, const RunOptions &options, MPI_Comm comm)
      {
        if (setup.driver.dynamic())
          return execute_dynamic<dim>(setup, options, comm);
        const auto    total_start = setup.total_start;
        const bool    root        = Utilities::MPI::this_mpi_process(comm) == 0;
        std::ostream *progress =
          (root && !options.quiet) ? &std::cout : nullptr;
        auto              &timings    = setup.timings;
        auto              &tria       = *setup.tria;
        auto              &cell_is_pd = setup.cell_is_pd;
        auto              &settings   = setup.settings;
        const auto        &fracture   = setup.fracture;
        const std::string &out_dir    = setup.out_dir;
        auto               start      = setup.setup_start;
        for (const auto &note : setup.notes)
          if (root)
            std::cerr << "pdfem: note: " << note << std::endl;

        // A scene may start with PD only around its cracks.
        const std::vector<Mesh::Crack<dim>> initial_cracks = settings.cracks;
        Fracture::extend_pd_region(tria,
                                   initial_cracks,
                                   fracture.adaptive_margin,
                                   cell_is_pd);
        auto system = std::make_unique<Coupling::CoupledSystem<dim>>(tria,
                                                                     cell_is_pd,
                                                                     settings);
        const Coupling::ProblemSize size = system->size();
        timings["setup"]                 = seconds_since(start);
        if (progress)
          *progress << "pdfem " << PDFEM_VERSION << ": " << setup.file << "\n"
                    << "  " << dim << "D, " << size.n_cells << " cells ("
                    << size.n_pd_cells << " PD), " << size.n_nodes << " nodes ("
                    << size.n_pd_nodes << " PD, " << size.n_interface_nodes
                    << " interface), " << size.n_dofs << " DoFs, "
                    << size.n_bonds << " bonds, "
                    << Utilities::MPI::n_mpi_processes(comm) << " rank(s)"
                    << std::endl;

        std::unique_ptr<Fracture::CrackGrowth<dim>> growth;
        if (fracture.criterion != "none")
          growth =
            std::make_unique<Fracture::CrackGrowth<dim>>(fracture,
                                                         settings.material,
                                                         initial_cracks,
                                                         *system,
                                                         setup.tip_at_end);
        const bool         mcts = fracture.criterion == "mcts";
        const bool         fc2  = fracture.criterion == "max principal stress";
        const bool         stretch = fracture.criterion == "critical stretch";
        const unsigned int n_tips  = growth ? growth->tips().size() : 0;

        // ---- history
        const auto               reaction_sets = system->reaction_names();
        std::vector<std::string> columns =
          base_history_columns<dim>(reaction_sets,
                                    !setup.reaction_group.empty());
        if (mcts)
          for (unsigned int k = 0; k < n_tips; ++k)
            {
              const std::string i = std::to_string(k);
              columns.insert(columns.end(),
                             {"tip" + i + "_x", "tip" + i + "_y"});
              if (dim == 3) // a crack-front point, with K_III
                columns.insert(columns.end(), {"tip" + i + "_z", "K_III" + i});
              columns.insert(columns.end(),
                             {"K_I" + i, "K_II" + i, "K_eq" + i, "J" + i});
            }
        if (fc2)
          columns.push_back("max_bond_principal_stress");
        if (stretch)
          columns.push_back("max_stretch_ratio");
        if (fracture.adaptive_margin > 0.)
          columns.push_back("pd_cells");
        columns.push_back("wall_seconds");
        IO::History history(out_dir + "/history.csv", columns, root);

        // The sum over a group of sets (PDLSM-FEM's RF command).
        const auto rf = [&]() {
          return group_reaction(system->reactions(), setup.reaction_group);
        };

        // ---- one row per converged step, progress, field output
        TrilinosWrappers::MPI::Vector u;
        system->initialize_vector(u);
        std::string                        exit_state = "completed", message;
        unsigned int                       n_steps    = 0;
        double                             last_load  = 0.;
        IO::FieldOutput<dim>               field_output(out_dir,
                                          dim == 2 &&
                                            !settings.material.plane_stress,
                                          settings.material.poissons_ratio);
        std::vector<std::array<Peak, dim>> peaks(reaction_sets.size() + 1);
        Fracture::Assessment               assessment;
        const auto record_step = [&](const Drivers::StepRecord &record) {
          n_steps                               = record.step;
          last_load                             = record.load_factor;
          const Coupling::ProblemSize s         = system->size();
          std::vector<double>         row       = {double(record.step),
                                                   record.time,
                                                   record.load_factor,
                                                   double(record.newton_iterations),
                                                   double(record.linear_iterations),
                                                   record.relative_residual,
                                                   double(s.n_broken_bonds),
                                                   system->max_damage()};
          const auto                  reactions = system->reactions();
          for (std::size_t set = 0; set < reactions.size(); ++set)
            for (unsigned int c = 0; c < dim; ++c)
              {
                row.push_back(reactions[set][c]);
                peaks[set][c].update(reactions[set][c],
                                     record.step,
                                     record.load_factor);
              }
          if (!setup.reaction_group.empty())
            for (unsigned int c = 0; c < dim; ++c)
              {
                row.push_back(rf()[c]);
                peaks.back()[c].update(rf()[c],
                                       record.step,
                                       record.load_factor);
              }
          if (mcts)
            for (const auto &tip : growth->tips())
              {
                row.insert(row.end(),
                           {tip.evaluated_at[0], tip.evaluated_at[1]});
                if (dim == 3)
                  row.insert(row.end(),
                             {tip.evaluated_at[dim - 1], tip.sif.K_III});
                row.insert(row.end(),
                           {tip.sif.K_I, tip.sif.K_II, tip.K_eq, tip.sif.J});
              }
          if (fc2 || stretch)
            row.push_back(assessment.max_driving_value);
          if (fracture.adaptive_margin > 0.)
            row.push_back(s.n_pd_cells);
          row.push_back(seconds_since(total_start));
          history.add_row(row);
          if (progress)
            {
              // step, load, iterations, broken bonds, time left
              const unsigned int n     = setup.driver.load_steps;
              const double       spent = seconds_since(setup.setup_start);
              *progress << "Step " << std::setw(4) << record.step << "/" << n
                        << "  t = " << std::setw(10) << std::setprecision(4)
                        << record.load_factor << "  iterations "
                        << record.newton_iterations << " (linear "
                        << record.linear_iterations
                        << ")  |r|/|f| = " << std::scientific
                        << std::setprecision(2) << record.relative_residual
                        << std::defaultfloat << "  broken bonds "
                        << s.n_broken_bonds;
              if (mcts)
                {
                  double K = 0.;
                  for (const auto &tip : growth->tips())
                    K = std::max(K, tip.K_eq);
                  *progress << "  K_eq/K_Ic " << std::setprecision(3)
                            << K / fracture.toughness;
                }
              if (fc2)
                *progress << "  sigma_1/sigma_ult " << std::setprecision(3)
                          << assessment.max_driving_value /
                               fracture.tensile_strength;
              if (stretch)
                *progress << "  s/s_c " << std::setprecision(3)
                          << assessment.max_driving_value;
              *progress << "  left ~" << std::fixed << std::setprecision(1)
                        << spent / record.step * (n - record.step) << " s"
                        << std::defaultfloat << std::endl;
            }
        };

        // ---- solve
        std::unique_ptr<Coupling::NodalResults<dim>> results;
        double     output_time = 0., criterion_time = 0.;
        const auto write_fields = [&](const double t) {
          const auto start = clock::now();
          if (setup.write_vtu)
            field_output.write(*system, *results, t);
          output_time += seconds_since(start);
        };
        Drivers::QuasiStaticDriver quasi_static(setup.driver);
        Drivers::StaticDriver      static_driver(setup.driver);
        try
          {
            if (setup.driver.type == "quasi-static")
              {
                const auto after_step = [&](const Drivers::StepRecord &record) {
                  const auto start = clock::now();
                  results = std::make_unique<Coupling::NodalResults<dim>>(
                    system->nodal_results(u));
                  assessment = growth ?
                                 growth->evaluate(*system, *results, true) :
                                 Fracture::Assessment();
                  criterion_time += seconds_since(start);
                  record_step(record);
                  if (setup.write_every > 0 &&
                      record.step % setup.write_every == 0 &&
                      record.step < setup.driver.load_steps)
                    write_fields(record.step);
                  Drivers::GrowthCheck check;
                  check.grew                = assessment.broken_bonds > 0;
                  check.critical_load_ratio = assessment.critical_load_ratio;
                  check.separated           = assessment.pieces > 1;
                  // The PD region follows the cracks: a new system on the
                  // same mesh and DoFs, with every crack so far cut.
                  if (check.grew && growth &&
                      Fracture::extend_pd_region(tria,
                                                 growth->segments(),
                                                 fracture.adaptive_margin,
                                                 cell_is_pd) > 0)
                    {
                      auto rebuilt   = settings;
                      rebuilt.cracks = initial_cracks;
                      system.reset();
                      system = std::make_unique<Coupling::CoupledSystem<dim>>(
                        tria, cell_is_pd, rebuilt);
                      std::vector<Mesh::Crack<dim>> grown(
                        growth->segments().begin() + initial_cracks.size(),
                        growth->segments().end());
                      system->break_bonds(grown);
                      growth->attach(*system);
                    }
                  return check;
                };
                quasi_static.run(
                  [&]() -> Drivers::SystemInterface & { return *system; },
                  u,
                  after_step);
              }
            else
              {
                static_driver.run(
                  *system, u, [&](const Drivers::StepRecord &record) {
                    if (growth)
                      {
                        results = std::make_unique<Coupling::NodalResults<dim>>(
                          system->nodal_results(u));
                        assessment = growth->evaluate(*system, *results, false);
                      }
                    record_step(record);
                  });
              }
          }
        catch (const RunFailure &e)
          {
            exit_state = e.exit_state;
            message    = e.what();
            if (root)
              std::cerr << "pdfem: run "
                        << (exit_state == "separated" ? "ended" : "stopped")
                        << ": " << message << std::endl;
          }
        const Drivers::DriverTimings &driver_timings =
          setup.driver.type == "quasi-static" ? quasi_static.timings() :
                                                static_driver.timings();
        timings["assembly"]  = driver_timings.assembly;
        timings["solve"]     = driver_timings.solve;
        timings["criterion"] = criterion_time;

        // ---- results
        start   = clock::now();
        results = std::make_unique<Coupling::NodalResults<dim>>(
          system->nodal_results(u));
        write_fields(n_steps);
        field_output.finish();
        if (setup.write_nodes_csv && root)
          IO::FieldOutput<dim>::write_nodes_csv(out_dir + "/nodes.csv",
                                                *results);
        if (growth && root)
          growth->write_paths(out_dir + "/crack_paths.vtk",
                              out_dir + "/crack_paths.csv");
        const Coupling::ProblemSize final_size = system->size();
        struct rusage               usage;
        getrusage(RUSAGE_SELF, &usage);
        const double peak_memory_mb = usage.ru_maxrss / 1024.; // Linux: kB
        output_time += seconds_since(start);
        timings["output"]          = output_time;
        const char *const phases[] = {
          "mesh", "setup", "assembly", "solve", "criterion", "output", "total"};
        timings["total"] = seconds_since(total_start);

        if (root)
          {
            std::ofstream  out(out_dir + "/summary.json");
            IO::JsonWriter json(out);
            json.begin_object();
            write_summary_header(
              json, setup, comm, exit_state, message, size, final_size);
            json.value("steps", static_cast<unsigned long>(n_steps));

            json.begin_object("final");
            json.value("load_factor", last_load);
            json.value("pd_cells", final_size.n_pd_cells);
            json.value("pd_nodes", final_size.n_pd_nodes);
            write_final_fields(json, *results);
            if (fc2)
              json.value("max_bond_principal_stress",
                         assessment.max_driving_value);
            if (stretch)
              json.value("max_stretch_ratio", assessment.max_driving_value);
            write_final_reactions(json,
                                  reaction_sets,
                                  system->reactions(),
                                  setup.reaction_group);
            if (mcts)
              {
                json.begin_object("crack_tips");
                for (unsigned int k = 0; k < n_tips; ++k)
                  {
                    const auto &tip = growth->tips()[k];
                    json.begin_object("tip" + std::to_string(k));
                    json.value("x", tip.position[0]);
                    json.value("y", tip.position[1]);
                    if (dim == 3) // a crack-front point
                      {
                        json.value("z", tip.position[dim - 1]);
                        json.value("front",
                                   static_cast<unsigned long>(tip.crack));
                        json.value("s", tip.s);
                        json.value("K_III", tip.sif.K_III);
                      }
                    json.value("active", tip.active ? "true" : "false");
                    json.value("K_I", tip.sif.K_I);
                    json.value("K_II", tip.sif.K_II);
                    json.value("K_eq", tip.K_eq);
                    json.value("J", tip.sif.J);
                    json.end_object();
                  }
                json.end_object();
              }
            json.end_object();

            // The largest reaction of each set (and of RF) over the run.
            const auto comps = component_names<dim>();
            json.begin_object("peak_reaction");
            for (std::size_t s = 0; s < peaks.size(); ++s)
              {
                if (s == reaction_sets.size() && setup.reaction_group.empty())
                  continue;
                json.begin_object(s < reaction_sets.size() ? reaction_sets[s] :
                                                             "RF");
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    json.value(comps[c], peaks[s][c].value);
                    json.value(comps[c] + "_step",
                               static_cast<unsigned long>(peaks[s][c].step));
                    json.value(comps[c] + "_load_factor", peaks[s][c].load);
                  }
                json.end_object();
              }
            json.end_object();

            json.begin_object("timings");
            for (const char *phase : phases)
              json.value(phase, timings[phase]);
            json.end_object();
            json.value("peak_memory_mb_rank0", peak_memory_mb);
            json.end_object();
          }

        if (progress)
          {
            *progress << "Exit state: " << exit_state << ". Results in "
                      << out_dir << "/" << std::endl;
            if (setup.print_timings)
              for (const char *phase : phases)
                *progress << "  " << std::setw(9) << std::left << phase
                          << std::right << std::setw(10) << std::fixed
                          << std::setprecision(3) << timings[phase] << " s"
                          << std::defaultfloat << std::endl;
          }
        return exit_state == "completed" || exit_state == "separated" ?
                 ExitCode::completed :
                 ExitCode::run_failure;
      }

#define INSTANTIATE(dim)                                                 \
  template int execute<dim>(Setup<dim> &, const RunOptions &, MPI_Comm); \
  template std::vector<std::string> base_history_columns<dim>(           \
    const std::vector<std::string> &, bool);                             \
  template void write_summary_header<dim>(IO::JsonWriter &,              \
                                          const Setup<dim> &,            \
                                          MPI_Comm,                      \
                                          const std::string &,           \
                                          const std::string &,           \
                                          const Coupling::ProblemSize &, \
                                          const Coupling::ProblemSize &);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem
