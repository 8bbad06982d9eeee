// SPDX-License-Identifier: LGPL-2.1-or-later
// What a Simulator prints and writes of itself: the progress lines and
// summary.json (the postprocessors add their own members).
#include <pdfem/base/config.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/io/atomic_file.h>
#include <pdfem/simulator/summary.h>

#include <deal.II/base/mpi.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>

#include "simulator_impl.h"
#include <sys/resource.h>

namespace pdfem
{
  using namespace dealii;
  using internal::seconds_since;


  template <int dim>
  void
  Simulator<dim>::Impl::print_header() const
  {
    if (!progress)
      return;
    const internal::KeepFormat   keep(*progress);
    const Coupling::ProblemSize &size = initial_size;
    *progress << "pdfem " << PDFEM_VERSION << ": " << setup.file << "\n"
              << "  " << dim << "D, " << size.n_cells << " cells ("
              << size.n_pd_cells << " PD), " << size.n_nodes << " nodes ("
              << size.n_pd_nodes << " PD, " << size.n_interface_nodes
              << " interface), " << size.n_dofs << " DoFs, " << size.n_bonds
              << " bonds, " << Utilities::MPI::n_mpi_processes(comm)
              << " rank(s), driver " << setup.driver.type << std::endl;
    if (size.n_pd_cells > 0)
      {
        *progress << "  PD model " << model_name;
        const auto constants = coupled->pd_model().constants();
        for (std::size_t i = 0; i < constants.size(); ++i)
          *progress << (i == 0 ? ": " : ", ") << constants[i].first << " = "
                    << constants[i].second;
        *progress << std::endl;
      }
  }

  template <int dim>
  void
  Simulator<dim>::Impl::print_static_progress(
    const Drivers::StepRecord &record,
    const unsigned long        n_broken_bonds) const
  {
    if (!progress)
      return;
    const internal::KeepFormat keep(*progress);
    // step, load, iterations, broken bonds, time left
    const unsigned int n     = driver->planned_steps();
    const double       spent = seconds_since(setup.setup_start);
    *progress << "Step " << std::setw(4) << record.step;
    // (Newton's step cuts add steps beyond the planned ones.)
    if (n > 0 && record.step <= n)
      *progress << "/" << n;
    *progress << "  t = " << std::setw(10) << std::setprecision(4)
              << record.load_factor << "  iterations "
              << record.newton_iterations << " (linear "
              << record.linear_iterations << ")  |r|/|f| = " << std::scientific
              << std::setprecision(2) << record.relative_residual
              << std::defaultfloat << "  broken bonds " << n_broken_bonds;
    if (criterion)
      *progress << criterion->progress(*cracks, assessment);
    // The largest reaction, the load the body carries.
    const auto reactions = coupled->reactions();
    if (!reactions.empty())
      {
        const auto  names   = coupled->reaction_names();
        std::size_t largest = 0;
        for (std::size_t i = 1; i < reactions.size(); ++i)
          if (reactions[i].norm() > reactions[largest].norm())
            largest = i;
        *progress << "  reaction "
                  << (largest < names.size() ? names[largest] : "") << " = (";
        for (unsigned int c = 0; c < dim; ++c)
          *progress << (c > 0 ? ", " : "") << std::setprecision(3)
                    << reactions[largest][c];
        *progress << ") N";
      }
    // By load: the load factor grows from 0 to 1 (step cuts and snap-back
    // paths make the step count a poor measure). A run that grows cracks
    // holds the load while they grow and may end before its last step (it
    // separates): there the step total is a bound, and so is the time left.
    const double t      = record.load_factor;
    const bool   growth = driver->grows_cracks() && n > 0;
    const double left =
      growth ?
        (record.step < n ? spent / record.step * (n - record.step) : 0.) :
        (t > 0. && t < 1. ? spent / t * (1. - t) : 0.);
    *progress << (growth ? "  left <= " : "  left ~") << std::fixed
              << std::setprecision(1) << left << " s" << std::defaultfloat
              << std::endl;
    // Linear solver Type = auto: a change of path in this step, and why.
    const auto switches = coupled->solver_switches();
    for (; printed_solver_switches < switches.size(); ++printed_solver_switches)
      *progress << "  " << switches[printed_solver_switches] << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::Impl::print_dynamic_progress(
    const Drivers::DynamicRecord &record,
    const unsigned long           n_broken_bonds) const
  {
    // Every 5 % of the steps, and at least every Output/Progress interval.
    const unsigned int every = std::max(1u, n_total_steps / 20);
    if (!progress ||
        (record.step % every != 0 && record.step < n_total_steps &&
         seconds_since(last_progress_line) < setup.progress_interval))
      return;
    last_progress_line = std::chrono::steady_clock::now();
    const internal::KeepFormat keep(*progress);
    const double               thickness = coupled->thickness();
    const double               spent     = seconds_since(run_start);
    *progress << "Step " << std::setw(6) << record.step << "/" << n_total_steps
              << "  t = " << std::scientific << std::setprecision(3)
              << record.time
              << "  E_kin = " << thickness * record.kinetic_energy
              << "  E_strain = " << thickness * record.strain_energy
              << "  energy error " << std::setprecision(2)
              << record.energy_error << std::defaultfloat << "  broken bonds "
              << n_broken_bonds << "  left ~" << std::fixed
              << std::setprecision(1)
              << (record.step > 0 && record.step < n_total_steps ?
                    spent / record.step * (n_total_steps - record.step) :
                    0.)
              << " s" << std::defaultfloat << std::endl;
  }

  template <int dim>
  std::string
  Simulator<dim>::Impl::write_running_marker() const
  {
    if (!root)
      return "";
    return IO::write_atomically(setup.out_dir + "/summary.json",
                                [&](std::ostream &out) {
                                  IO::JsonWriter json(out);
                                  json.begin_object();
                                  json.value("pdfem_version", PDFEM_VERSION);
                                  json.value("scene", setup.name);
                                  json.value("input_file", setup.file);
                                  json.value("exit_state", "running");
                                  json.value("message",
                                             "the run has not ended: it is "
                                             "running, or it was killed");
                                  json.end_object();
                                });
  }

  template <int dim>
  std::string
  Simulator<dim>::Impl::write_summary() const
  {
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    const Coupling::ProblemSize final_size = coupled->size(); // collective
    if (!root)
      return "";
    // ru_maxrss: kB on Linux
    return IO::write_atomically(
      setup.out_dir + "/summary.json", [&](std::ostream &out) {
        write_summary(out, final_size, usage.ru_maxrss / 1024.);
      });
  }

  template <int dim>
  void
  Simulator<dim>::Impl::write_summary(std::ostream                &out,
                                      const Coupling::ProblemSize &final_size,
                                      const double peak_memory_mb) const
  {
    IO::JsonWriter json(out);
    json.begin_object();
    Summary::write_header(
      json, setup, comm, exit_state, message, initial_size, final_size);
    json.value("steps", static_cast<unsigned long>(n_steps));

    json.begin_object("final");
    if (driver->dynamic())
      json.value("time", time_step_record.time);
    json.value("load_factor", load_factor);
    json.value("pd_cells", final_size.n_pd_cells);
    json.value("pd_nodes", final_size.n_pd_nodes);
    Summary::write_field_extremes(json, *results);
    if (criterion)
      criterion->write_final(*cracks, assessment, json);
    for (const auto &p : postprocessors)
      p->write_final(json);
    if (!driver->dynamic()) // dynamic ones: the energy balance's section
      driver->write_summary(json);
    json.end_object();
    if (initial_size.n_pd_cells > 0)
      {
        json.begin_object("pd_model");
        json.value("name", model_name);
        for (const auto &[name, value] : coupled->pd_model().constants())
          json.value(name, value);
        json.end_object();
      }
    for (const auto &p : postprocessors)
      p->write_sections(json);
    coupled->write_solver_summary(json);

    json.begin_object("timings");
    for (const auto &[phase, seconds] : setup.timings)
      json.value(phase, seconds);
    json.begin_object("setup_phases");
    for (const auto &[phase, seconds] : setup_phases)
      json.value(phase, seconds);
    json.end_object();
    json.end_object();
    json.value("peak_memory_mb_rank0", peak_memory_mb);
    json.end_object();
  }

  template <int dim>
  void
  Simulator<dim>::Impl::print_end() const
  {
    if (!progress)
      return;
    const internal::KeepFormat keep(*progress);
    *progress << "Exit state: " << exit_state << ". Results in "
              << setup.out_dir << "/" << std::endl;
    if (!setup.print_timings)
      return;
    const auto line = [&](const std::string &name, const double seconds) {
      *progress << "  " << std::setw(24) << std::left << name << std::right
                << std::setw(10) << std::fixed << std::setprecision(3)
                << seconds << " s" << std::defaultfloat << std::endl;
    };
    for (const auto &[phase, seconds] : setup.timings)
      {
        line(phase, seconds);
        if (phase == "setup")
          for (const auto &[part, part_seconds] : setup_phases)
            line("  " + part, part_seconds);
      }
  }

  template <int dim>
  void
  Simulator<dim>::Impl::write_time_step_row(
    const Drivers::DynamicRecord &record)
  {
    // Reactions of the supports (f_int - f_ext over each set) from the
    // forces the integrator evaluated last (at this u and t).
    if (!coupled->reaction_names().empty())
      coupled->update_reactions();
    const Coupling::ProblemSize s = coupled->size();
    add_history_row({double(record.step),
                     record.time,
                     record.time / setup.driver.end_time,
                     0.,
                     double(record.linear_iterations),
                     0.,
                     double(s.n_broken_bonds),
                     coupled->max_damage()});
    print_dynamic_progress(record, s.n_broken_bonds);
  }

#define INSTANTIATE(dim)                                                   \
  template void Simulator<dim>::Impl::print_header() const;                \
  template void Simulator<dim>::Impl::print_static_progress(               \
    const Drivers::StepRecord &, unsigned long) const;                     \
  template void Simulator<dim>::Impl::print_dynamic_progress(              \
    const Drivers::DynamicRecord &, unsigned long) const;                  \
  template std::string Simulator<dim>::Impl::write_summary() const;        \
  template std::string Simulator<dim>::Impl::write_running_marker() const; \
  template void        Simulator<dim>::Impl::print_end() const;            \
  template void        Simulator<dim>::Impl::write_time_step_row(          \
    const Drivers::DynamicRecord &);
  PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace pdfem
