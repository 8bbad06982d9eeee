// SPDX-License-Identifier: LGPL-2.1-or-later
// A dynamic run (Driver/Type = explicit or newmark): the coupled system,
// the time integrator, history.csv with the energy balance, VTU and
// summary.json.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/drivers/central_difference.h>
#include <pdfem/drivers/newmark.h>
#include <pdfem/fracture/crack_growth.h>
#include <pdfem/io/field_output.h>
#include <pdfem/io/history.h>
#include <pdfem/io/json_writer.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>

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
      } // namespace

      template <int dim>
      int
      execute_dynamic(Setup<dim>       &setup,
                      const RunOptions &options,
                      MPI_Comm          comm)
      {
        const bool    root = Utilities::MPI::this_mpi_process(comm) == 0;
        std::ostream *progress =
          (root && !options.quiet) ? &std::cout : nullptr;
        const Parameters::Driver &prm      = setup.driver;
        auto                     &timings  = setup.timings;
        auto                     &settings = setup.settings;
        auto                      start    = setup.setup_start;
        for (const auto &note : setup.notes)
          if (root)
            std::cerr << "pdfem: note: " << note << std::endl;
        if (root && prm.type == "explicit" && prm.time_step == 0. &&
            prm.safety_factor > 1.)
          std::cerr << "pdfem: note: Driver/Time step safety factor = "
                    << prm.safety_factor
                    << " is above 1: the central difference is unstable"
                    << std::endl;

        Coupling::CoupledSystem<dim> system(*setup.tria,
                                            setup.cell_is_pd,
                                            settings);
        const Coupling::ProblemSize  size = system.size();
        timings["setup"]                  = seconds_since(start);
        if (progress)
          *progress << "pdfem " << PDFEM_VERSION << ": " << setup.file << "\n"
                    << "  " << dim << "D, " << size.n_cells << " cells ("
                    << size.n_pd_cells << " PD), " << size.n_nodes << " nodes ("
                    << size.n_pd_nodes << " PD, " << size.n_interface_nodes
                    << " interface), " << size.n_dofs << " DoFs, "
                    << size.n_bonds << " bonds, "
                    << Utilities::MPI::n_mpi_processes(comm) << " rank(s), "
                    << (prm.type == "explicit" ? "central difference" :
                                                 "Newmark")
                    << std::endl;

        // ---- monitor points: the nearest nodes
        std::vector<unsigned int> monitor_nodes;
        for (const auto &mp : prm.monitor_points)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = mp.point[d];
            monitor_nodes.push_back(system.nearest_node(p));
          }

        // ---- history
        const double             thickness     = system.thickness();
        const auto               reaction_sets = system.reaction_names();
        std::vector<std::string> columns =
          base_history_columns<dim>(reaction_sets,
                                    !setup.reaction_group.empty());
        for (const char *c : {"time_step",
                              "kinetic_energy",
                              "strain_energy",
                              "external_work",
                              "dissipated_energy",
                              "energy_error"})
          columns.push_back(c);
        for (const auto &mp : prm.monitor_points)
          for (const auto &c : component_names<dim>())
            columns.push_back("u_" + IO::History::column_name(mp.name) + "_" +
                              c);
        columns.push_back("wall_seconds");
        IO::History history(setup.out_dir + "/history.csv", columns, root);

        // ---- initial state
        TrilinosWrappers::MPI::Vector u, v0, r;
        system.initialize_vector(u);
        system.interpolate(prm.initial_velocity, "Driver/Initial velocity", v0);

        const unsigned int n_expected =
          prm.time_step > 0. ? static_cast<unsigned int>(std::ceil(
                                 prm.end_time / prm.time_step - 1e-9)) :
                               0;
        Drivers::CentralDifference explicit_driver(prm);
        Drivers::Newmark           newmark_driver(prm);
        Drivers::DynamicRecord     last;
        double                     max_abs_error = 0.;
        unsigned int               n_written     = 0;
        unsigned int               n_total       = n_expected;
        double                     dt_used       = prm.time_step;
        const auto                 run_start     = clock::now();
        auto on_step = [&](const Drivers::DynamicRecord &record) {
          last    = record;
          dt_used = record.time_step;
          max_abs_error =
            std::max(max_abs_error, std::abs(record.energy_error));
          if (n_total == 0 && record.time_step > 0.)
            n_total = static_cast<unsigned int>(
              std::ceil(prm.end_time / record.time_step - 1e-9));
          const bool last_step = record.step >= n_total;
          if (record.step == 0 && progress)
            {
              *progress << "  time step " << record.time_step << " s";
              if (prm.type == "explicit")
                {
                  const auto &e = explicit_driver.stability();
                  *progress << " = " << record.time_step / e.critical_time_step
                            << " x dt_crit; dt_crit = 2/omega_max = "
                            << e.critical_time_step << " s (power iteration, "
                            << e.iterations << " iterations, last change "
                            << e.last_change << ")";
                }
              *progress << "; " << n_total << " steps to t = " << prm.end_time
                        << " s" << std::endl;
            }
          if (record.step % prm.history_interval != 0 && !last_step &&
              !(record.energy_error > prm.energy_tolerance) &&
              std::isfinite(record.energy_error))
            return;
          ++n_written;
          // Reactions of the supports (f_int - f_ext over each set) from
          // the forces the integrator evaluated last (at this u and t).
          if (!reaction_sets.empty())
            system.update_reactions();
          const Coupling::ProblemSize s         = system.size();
          std::vector<double>         row       = {double(record.step),
                                                   record.time,
                                                   record.time / prm.end_time,
                                                   0.,
                                                   double(record.linear_iterations),
                                                   0.,
                                                   double(s.n_broken_bonds),
                                                   system.max_damage()};
          const auto                  reactions = system.reactions();
          for (const auto &R : reactions)
            for (unsigned int c = 0; c < dim; ++c)
              row.push_back(R[c]);
          if (!setup.reaction_group.empty())
            {
              const auto R = group_reaction(reactions, setup.reaction_group);
              for (unsigned int c = 0; c < dim; ++c)
                row.push_back(R[c]);
            }
          row.push_back(record.time_step);
          for (const double e : {record.kinetic_energy,
                                 record.strain_energy,
                                 record.external_work,
                                 record.dissipated_energy})
            row.push_back(thickness * e);
          row.push_back(record.energy_error);
          for (const unsigned int k : monitor_nodes)
            {
              const auto d = system.node_displacement(u, k);
              for (unsigned int c = 0; c < dim; ++c)
                row.push_back(d[c]);
            }
          row.push_back(seconds_since(setup.total_start));
          history.add_row(row);
          const unsigned int every = std::max(1u, n_total / 20);
          if (progress && (record.step % every == 0 || last_step))
            {
              const double spent = seconds_since(run_start);
              *progress << "Step " << std::setw(6) << record.step << "/"
                        << n_total << "  t = " << std::scientific
                        << std::setprecision(3) << record.time
                        << "  E_kin = " << thickness * record.kinetic_energy
                        << "  E_strain = " << thickness * record.strain_energy
                        << "  energy error " << std::setprecision(2)
                        << record.energy_error << std::defaultfloat
                        << "  broken bonds " << s.n_broken_bonds << "  left ~"
                        << std::fixed << std::setprecision(1)
                        << (record.step > 0 ?
                              spent / record.step * (n_total - record.step) :
                              0.)
                        << " s" << std::defaultfloat << std::endl;
            }
        };

        Drivers::AfterStep after_step;
        if (setup.make_after_step)
          after_step = setup.make_after_step(system);
        // Dynamic fracture: the maximum principal stress criterion after
        // every step (specs/004 §2.3: PDLSM-FEM's FC 2 in DYNAMIC runs); the
        // integrator books the released energy and, for Newmark,
        // refactorises.
        std::unique_ptr<Fracture::CrackGrowth<dim>> growth;
        double                                      criterion_time = 0.;
        if (setup.fracture.criterion == "max principal stress" ||
            setup.fracture.criterion == "critical stretch")
          {
            growth =
              std::make_unique<Fracture::CrackGrowth<dim>>(setup.fracture,
                                                           settings.material,
                                                           settings.cracks,
                                                           system,
                                                           setup.tip_at_end);
            after_step = [&](const TrilinosWrappers::MPI::Vector &u_now,
                             double) {
              const auto start   = clock::now();
              const auto results = system.nodal_results(u_now);
              const auto a       = growth->evaluate(system, results, true);
              criterion_time += seconds_since(start);
              return a.broken_bonds > 0;
            };
          }

        std::string                exit_state = "completed", message;
        Drivers::DynamicTimings    dyn_timings;
        Drivers::StabilityEstimate stability;
        Drivers::InstabilityReport instability;
        unsigned int               factorizations = 0;
        try
          {
            if (prm.type == "explicit")
              {
                explicit_driver.run(system, u, v0, on_step, after_step);
              }
            else
              newmark_driver.run(system, u, v0, on_step, after_step);
          }
        catch (const RunFailure &e)
          {
            exit_state = e.exit_state;
            message    = e.what();
            if (root)
              std::cerr << "pdfem: run stopped: " << message << std::endl;
          }
        if (prm.type == "explicit")
          {
            dyn_timings = explicit_driver.timings();
            stability   = explicit_driver.stability();
            instability = explicit_driver.instability();
          }
        else
          {
            dyn_timings    = newmark_driver.timings();
            factorizations = newmark_driver.n_factorizations();
          }
        timings["assembly"] = dyn_timings.internal_force +
                              dyn_timings.external_force +
                              dyn_timings.factorize;
        timings["solve"]     = dyn_timings.solve + dyn_timings.update;
        timings["criterion"] = criterion_time;

        // Total mass (lumped, per component, for the thickness): rho x volume.
        const double total_mass =
          thickness * system.lumped_mass().l1_norm() / dim;

        // ---- results (reactions at the last state)
        start = clock::now();
        if (!reaction_sets.empty())
          system.residual(u, last.time, r, false);
        const auto                        final_reactions = system.reactions();
        const Coupling::ProblemSize       final_size      = system.size();
        const Coupling::NodalResults<dim> results = system.nodal_results(u);
        IO::FieldOutput<dim>              field_output(setup.out_dir,
                                          dim == 2 &&
                                            !settings.material.plane_stress,
                                          settings.material.poissons_ratio);
        if (setup.write_vtu)
          {
            field_output.write(system, results, last.time);
            field_output.finish();
          }
        if (setup.write_nodes_csv && root)
          IO::FieldOutput<dim>::write_nodes_csv(setup.out_dir + "/nodes.csv",
                                                results);
        if (growth && root)
          growth->write_paths(setup.out_dir + "/crack_paths.vtk",
                              setup.out_dir + "/crack_paths.csv");
        struct rusage usage;
        getrusage(RUSAGE_SELF, &usage);
        timings["output"] = seconds_since(start);
        timings["total"]  = seconds_since(setup.total_start);

        if (root)
          {
            std::ofstream  out(setup.out_dir + "/summary.json");
            IO::JsonWriter json(out);
            json.begin_object();
            write_summary_header(
              json, setup, comm, exit_state, message, size, final_size);
            json.value("steps", static_cast<unsigned long>(last.step));

            json.begin_object("final");
            json.value("time", last.time);
            json.value("load_factor", last.time / prm.end_time);
            write_final_fields(json, results);
            write_final_reactions(json,
                                  reaction_sets,
                                  final_reactions,
                                  setup.reaction_group);
            json.end_object();

            // The dynamic run: step, stability, energy balance, cost.
            json.begin_object("dynamics");
            json.value("integrator",
                       prm.type == "explicit" ? "central difference" :
                                                "newmark");
            json.value("time_step", dt_used);
            json.value("end_time", prm.end_time);
            if (prm.type == "explicit")
              {
                json.value("critical_time_step", stability.critical_time_step);
                json.value("time_step_ratio",
                           stability.critical_time_step > 0. ?
                             dt_used / stability.critical_time_step :
                             0.);
                json.value("omega_max", stability.omega_max);
                json.value("eigenvalue_iterations",
                           static_cast<unsigned long>(stability.iterations));
                json.value("eigenvalue_last_change", stability.last_change);
              }
            else
              {
                json.value("newmark_beta", prm.newmark_beta);
                json.value("newmark_gamma", prm.newmark_gamma);
                json.value("factorizations",
                           static_cast<unsigned long>(factorizations));
              }
            json.value("mass", prm.mass);
            json.value("total_mass", total_mass);
            json.value("kinetic_energy", thickness * last.kinetic_energy);
            json.value("strain_energy", thickness * last.strain_energy);
            json.value("external_work", thickness * last.external_work);
            json.value("dissipated_energy", thickness * last.dissipated_energy);
            json.value("energy_error", last.energy_error);
            json.value("max_abs_energy_error", max_abs_error);
            if (instability.unstable)
              {
                json.value("growth_per_step", instability.growth_per_step);
                json.value("estimated_critical_time_step",
                           instability.estimated_critical_step);
                json.value("time_step_reduction",
                           instability.recommended_factor);
                json.value("recommended_time_step",
                           instability.recommended_time_step);
              }
            json.end_object();

            json.begin_object("timings");
            for (const char *phase : {"mesh",
                                      "setup",
                                      "assembly",
                                      "solve",
                                      "criterion",
                                      "output",
                                      "total"})
              json.value(phase, timings[phase]);
            const double n = std::max(1u, dyn_timings.n_steps);
            json.value("time_loop", dyn_timings.steps);
            json.value("seconds_per_step", dyn_timings.steps / n);
            json.value("internal_force_per_step",
                       dyn_timings.internal_force / n);
            json.value("external_force_per_step",
                       dyn_timings.external_force / n);
            json.value("update_per_step", dyn_timings.update / n);
            json.value("solve_per_step", dyn_timings.solve / n);
            json.value("factorize", dyn_timings.factorize);
            json.value("eigenvalue", dyn_timings.eigenvalue);
            json.end_object();
            json.value("peak_memory_mb_rank0", usage.ru_maxrss / 1024.);
            json.end_object();
          }

        if (progress)
          {
            if (prm.type == "explicit")
              *progress << std::setprecision(6)
                        << "  dt_crit = " << stability.critical_time_step
                        << " s (omega_max = " << stability.omega_max
                        << " 1/s), dt = " << dt_used << " s = "
                        << (stability.critical_time_step > 0. ?
                              dt_used / stability.critical_time_step :
                              0.)
                        << " dt_crit" << std::endl;
            *progress << "Exit state: " << exit_state << ". Results in "
                      << setup.out_dir << "/" << std::endl;
            if (setup.print_timings)
              *progress << "  time loop " << dyn_timings.steps << " s, "
                        << dyn_timings.steps /
                             std::max(1u, dyn_timings.n_steps) * 1e3
                        << " ms per step" << std::endl;
          }
        return exit_state == "completed" ? ExitCode::completed :
                                           ExitCode::run_failure;
      }

#define INSTANTIATE(dim) \
  template int execute_dynamic<dim>(Setup<dim> &, const RunOptions &, MPI_Comm);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem
