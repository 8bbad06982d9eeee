// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-study: run a scene over a grid of parameter values and chart its
// accuracy against its cost.
//
//   pdfem-study scene.prm --vary "Peridynamics/Horizon factor=3,4"
//               --output final.crack_tips.tip0.K_I --reference 3.98e6
//
// Every combination of the --vary values is one run, done in this process by
// Scene::run (the process starts once for the study), in its own folder;
// `--vary ranks=1,2` runs are launched as `mpirun -np K pdfem`. The study
// writes study.csv (one row per run), study.png (error against time, the
// Pareto front) and a table on stdout. See doc/tools.md, "pdfem-study".
//
// This file: the help text and main(); the pieces are declared in
// pdfem_study.h.
#include "pdfem_study.h"

#include <pdfem/base/interrupts.h>
#include <pdfem/base/mpi_startup.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>

extern char **environ;

namespace pdfem_study
{
  const char *const help_text =
    R"(pdfem-study: run a scene over a grid of parameter values; chart its error against its time.

Usage:
  pdfem-study SCENE.prm --vary "Section/Entry=V1,V2,..." [--vary ...]
              --output KEY [--output ...] [--reference VALUE [--reference ...] | --reference run:"PATH=V;..."]
              [--set "Section/Entry=VALUE"]... [-o DIR] [--no-chart] [--mpiexec PROGRAM]

  --vary PATH=V1,V2,...  a parameter and its values; the runs are every combination of the
                         --vary values (the first --vary varies slowest). ranks=1,2,... runs
                         `mpirun -np K pdfem` (beside pdfem-study) instead of in this process
  --output KEY           a number of summary.json to measure, as a dotted key, e.g.
                         final.max_displacement.x, final.max_stress.xx, peak_reaction.top.y,
                         final.crack_tips.tip0.K_I (repeatable)
  --reference VALUE      the exact value of the output (one per --output, in their order), or
  --reference run:"PATH=V;..."  one extra run with these overrides (e.g. a finer mesh) whose
                         outputs are the reference. Errors are |v - ref| / |ref| (|v| if ref = 0)
  --set PATH=VALUE       an override for every run (repeatable)
  -o DIR                 the study folder (default study-<scene name>); run k in DIR/run_00k,
                         the reference run in DIR/reference
  --no-chart             do not draw DIR/study.png
  --mpiexec PROGRAM      the MPI launcher of ranks runs (default mpirun)

Writes DIR/study.csv (one row per run: the varied values, in_process, exit_state, the outputs,
their references and errors, wall_seconds, pdfem_total_seconds, peak_memory_mb, dofs, bonds,
pareto) and, with pdfem-plot beside pdfem-study (VTK), DIR/study.png: the error of the first
output against the wall time, log-log, each run a marker, the Pareto front a line.
Exit status: 0 every run completed (or separated); 2 bad input, one line on stderr, nothing run
(an output key the first finished run does not have stops the study there); 3 a run failed
(it stays in study.csv with its exit state; the study goes on), or SIGINT/SIGTERM stopped the
study after the run it came in (a second signal ends it at once).
)";
} // namespace pdfem_study

namespace
{
  using namespace pdfem_study;

  /// The overrides of a check, and the option to blame when it fails.
  struct Check
  {
    std::vector<Override> overrides;
    std::string           option;
  };

  /// Every parameter check before any run: the scene with --set, each
  /// varied value alone, each point of the grid, the reference run.
  /// Throws UsageError with the first fault.
  void
  check_input(const Options &options, const std::vector<Point> &grid)
  {
    std::vector<Check> checks;
    // Without --set, a fault is the scene's own (the message names the file).
    checks.push_back({options.sets, options.sets.empty() ? "" : "--set"});
    for (const auto &v : options.vary)
      if (v.path != ranks_parameter)
        for (const auto &value : v.values)
          {
            auto overrides = options.sets;
            overrides.emplace_back(v.path, value);
            checks.push_back(
              {overrides, "--vary \"" + v.path + "=" + value + "\""});
          }
    if (options.vary.size() > 1)
      for (const auto &point : grid)
        checks.push_back({point.overrides,
                          "--vary: run " + std::to_string(point.number) + " (" +
                            describe(options, point) + ")"});
    if (options.reference.kind == Reference::run)
      {
        auto overrides = options.sets;
        overrides.insert(overrides.end(),
                         options.reference.overrides.begin(),
                         options.reference.overrides.end());
        checks.push_back({overrides, "--reference " + options.reference.text});
      }
    for (const auto &check : checks)
      if (const std::string fault = check_scene(options.scene, check.overrides);
          !fault.empty())
        throw UsageError(check.option.empty() ? fault :
                                                check.option + ": " + fault);

    bool launched = false;
    for (const auto &point : grid)
      launched = launched || point.ranks > 0;
    if (launched)
      {
        if (find_executable(options.mpiexec).empty())
          throw UsageError("--mpiexec: '" + options.mpiexec +
                           "' is not an executable (allowed: an MPI launcher "
                           "such as mpirun, for --vary ranks=...)");
        if (find_executable(program_folder() + "/pdfem").empty())
          throw UsageError("--vary ranks: there is no pdfem beside pdfem-study "
                           "in " +
                           program_folder() +
                           " (allowed: an installed pdfem with pdfem-study)");
        // Open MPI binds each rank to one core when it starts one or two:
        // a 1-rank run would lose its threads (pdfem then uses one; its
        // note says so). Unbound, K ranks share the machine's cores as an
        // in-process run does. A binding the user chose stays. (The runs
        // get the environment pdfem-study started with, not setenv()'s.)
        const std::string unbound     = "OMPI_MCA_hwloc_base_binding_policy=";
        auto             &environment = original_environment();
        if (std::none_of(environment.begin(),
                         environment.end(),
                         [&](const std::string &e) {
                           return e.compare(0, unbound.size(), unbound) == 0;
                         }))
          environment.push_back(unbound + "none");
      }
  }

  /// An --output key the summary does not have as a number: the one-line
  /// message (with the numbers it has under the longest prefix that exists),
  /// or "".
  std::string
  missing_output(const Options     &options,
                 const Json        &summary,
                 const std::string &file)
  {
    for (const auto &key : options.outputs)
      {
        if (!std::isnan(summary.number_at(key)))
          continue;
        std::string prefix = key;
        while (!prefix.empty() && summary.find(prefix) == nullptr)
          prefix = prefix.substr(
            0, prefix.rfind('.') == std::string::npos ? 0 : prefix.rfind('.'));
        const Json *under = prefix.empty() ? &summary : summary.find(prefix);
        std::vector<std::string> keys = under->number_keys(prefix);
        std::string              list;
        for (std::size_t i = 0; i < keys.size() && i < 30; ++i)
          list += (i ? ", " : "") + keys[i];
        if (keys.size() > 30)
          list += ", ... (" + std::to_string(keys.size()) + " in all)";
        return "--output " + key + ": " + file +
               " has no such number (allowed" +
               (prefix.empty() ? std::string() : " under '" + prefix + "'") +
               ": " + (list.empty() ? "none" : list) + ")";
      }
    return "";
  }

  /// SIGINT or SIGTERM received between runs or during an mpirun run.
  volatile std::sig_atomic_t stop_signal = 0;

  extern "C" void
  remember_stop(int s)
  {
    stop_signal = s;
    std::signal(s, SIG_DFL); // a second one ends the study at once
  }

  /// Catches SIGINT and SIGTERM (unless they are ignored, as in a
  /// background job), so that the study ends after the run they come in.
  void
  catch_stop_signals()
  {
    for (int s : {SIGINT, SIGTERM})
      if (std::signal(s, remember_stop) == SIG_IGN)
        std::signal(s, SIG_IGN);
  }

  /// The signal that asks the study to stop (0: none): ours, or the one
  /// Scene::run's handler took during the last in-process run (which ends
  /// that run after its step: a run of one step still completes).
  int
  stop_requested()
  {
    return stop_signal != 0 ?
             static_cast<int>(stop_signal) :
             pdfem::StopOnSignals::stop_requested(MPI_COMM_WORLD);
  }

  /// "completed, 1.23 s" for the progress line.
  std::string
  outcome(const RunResult &r)
  {
    return r.exit_state + ", " + format(r.wall_seconds, 3) + " s" +
           (r.in_process ? "" : " (mpirun)");
  }
} // namespace

int
main(int argc, char **argv)
{
  for (char **e = environ; e != nullptr && *e != nullptr; ++e)
    original_environment().emplace_back(*e);

  Options options;
  try
    {
      bool help = false;
      options   = parse_command_line(argc, argv, help);
      if (help)
        {
          std::cout << help_text;
          return success;
        }
    }
  catch (const UsageError &e)
    {
      std::cerr << "pdfem-study: error: " << e.what() << std::endl;
      return bad_input;
    }

  pdfem::prepare_mpi_singleton_startup();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, dealii::numbers::invalid_unsigned_int);
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "pdfem-study: error: pdfem-study runs as one process "
                     "(allowed: pdfem-study without mpirun; --vary ranks=1,2 "
                     "launches parallel runs)"
                  << std::endl;
      return bad_input;
    }

  catch_stop_signals();
  std::vector<Point> grid;
  try
    {
      grid = make_grid(options);
      check_input(options, grid);
      std::error_code ec;
      std::filesystem::create_directories(options.directory, ec);
      if (ec)
        throw UsageError("-o: cannot create the folder '" + options.directory +
                         "': " + ec.message() +
                         " (allowed: a writable folder)");
    }
  catch (const UsageError &e)
    {
      std::cerr << "pdfem-study: error: " << e.what() << std::endl;
      return bad_input;
    }

  const std::string &dir = options.directory;
  std::cout << "pdfem-study: " << scene_name(options.scene) << ", "
            << grid.size() << " run(s) into " << dir << "/" << std::endl;
  bool                keys_checked = false;
  bool                failed       = false;
  std::vector<double> reference(options.outputs.size(), missing);

  // Stops the study at an unknown output key: exit status 2.
  auto check_keys = [&](const RunResult &r, const std::string &folder) {
    if (keys_checked || !r.finished() || !r.summary)
      return true;
    keys_checked = true;
    const std::string fault =
      missing_output(options, *r.summary, folder + "/summary.json");
    if (!fault.empty())
      std::cerr << "pdfem-study: error: " << fault << std::endl;
    return fault.empty();
  };

  if (options.reference.kind == Reference::values)
    reference = options.reference.numbers;
  else if (options.reference.kind == Reference::run)
    {
      auto overrides = options.sets;
      overrides.insert(overrides.end(),
                       options.reference.overrides.begin(),
                       options.reference.overrides.end());
      std::cout << "reference run (" << options.reference.text.substr(4)
                << "): " << std::flush;
      const RunResult r = run_in_process(options.scene,
                                         overrides,
                                         dir + "/reference",
                                         options.outputs);
      std::cout << outcome(r) << std::endl;
      if (const int signal = stop_requested(); signal != 0)
        {
          std::cout << pdfem::StopOnSignals::name(signal)
                    << ": the study stops after the reference run" << std::endl;
          return failed_runs;
        }
      if (!check_keys(r, dir + "/reference"))
        return bad_input;
      if (r.finished())
        reference = r.outputs;
      else
        failed = true;
    }

  std::vector<Row> rows;
  for (const auto &point : grid)
    {
      std::cout << "run " << point.number << "/" << grid.size() << " ("
                << describe(options, point) << "): " << std::flush;
      const std::string folder = dir + "/" + point.folder;
      Row               row{point, {}, {}, -1};
      row.result = point.ranks > 0 ? run_launched(options.mpiexec,
                                                  point.ranks,
                                                  options.scene,
                                                  point.overrides,
                                                  folder,
                                                  options.outputs) :
                                     run_in_process(options.scene,
                                                    point.overrides,
                                                    folder,
                                                    options.outputs);
      std::cout << outcome(row.result) << std::endl;
      if (!check_keys(row.result, folder))
        return bad_input;
      for (std::size_t k = 0; k < options.outputs.size(); ++k)
        row.errors.push_back(
          row.result.finished() ?
            relative_error(row.result.outputs[k], reference[k]) :
            missing);
      failed = failed || !row.result.finished();
      rows.push_back(row);
      if (const int signal = stop_requested();
          signal != 0 || row.result.exit_state == "interrupted")
        {
          std::cout << (signal != 0 ? pdfem::StopOnSignals::name(signal) :
                                      "the run was interrupted")
                    << ": the study stops after run " << point.number << " of "
                    << grid.size() << std::endl;
          failed = true;
          break;
        }
    }

  mark_pareto(rows);
  try
    {
      write_csv(dir + "/study.csv", options, rows, reference);
    }
  catch (const std::exception &e)
    {
      std::cerr << "pdfem-study: error: " << e.what() << std::endl;
      return failed_runs;
    }
  print_table(options, rows, reference);
  std::cout << "table: " << dir << "/study.csv" << std::endl;
  if (options.chart)
    std::cout << "chart: " << draw_chart(dir, options, rows) << std::endl;
  return failed ? failed_runs : success;
}
