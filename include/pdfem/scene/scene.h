// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SCENE_SCENE_H
#define PDFEM_SCENE_SCENE_H

#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

namespace pdfem
{
  namespace Parameters
  {
    struct Scene;
  }
  template <int dim>
  struct RunPlugins;

  namespace Scene
  {
    /** Command-line choices that override the scene file. */
    struct RunOptions
    {
      /// Output folder; empty: the scene's `Output/Directory` or its default.
      std::string output_directory;
      /// No progress lines on the terminal.
      bool quiet = false;
      /// Parameter overrides ("Section/Entry", "value") from `--set`.
      std::vector<std::pair<std::string, std::string>> overrides;
      /// `--restart`: go on from the checkpoint in this output folder
      /// (which is then the output folder, unless --output names it).
      std::string restart;
      /// `--print-parameters` with a scene: print its parameters as they
      /// are resolved (every --set applied, the mesh file made absolute;
      /// what parameters.prm of a run holds) and do nothing else.
      bool print_parameters = false;
    };

    /** Exit codes of a run (also the `pdfem` process exit status). */
    enum ExitCode : int
    {
      completed   = 0,
      input_error = 2,
      run_failure = 3
    };

    /**
     * Run one scene file (`.prm`): read and validate it, mesh, set up the
     * coupled system, run the driver, write history.csv, summary.json and
     * the field output. Bad input is reported (on rank 0, to stderr) as one
     * line before any work; a failure during the run (singular matrix,
     * divergence) is written to summary.json as the exit state.
     */
    int
    run(const std::string &file, const RunOptions &options, MPI_Comm comm);

    /**
     * The plugins the parameter file @p prm names (its driver, crack
     * criterion, PD model and linear solver), made and checked by
     * make_plugins(). Throws InputError.
     */
    template <int dim>
    RunPlugins<dim>
    plugins_of(const Parameters::Scene &prm);
  } // namespace Scene
} // namespace pdfem

#endif
