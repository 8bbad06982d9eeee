// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the scene module: a run set up from any input (a pdfem .prm
// scene or a PDLSM-FEM command file), and the part that executes it.
#ifndef PDFEM_SOURCE_SCENE_SCENE_INTERNAL_H
#define PDFEM_SOURCE_SCENE_SCENE_INTERNAL_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/io/parameters.h>
#include <pdfem/scene/scene.h>
#include <pdfem/simulator/simulator.h>
#include <pdfem/simulator/summary.h>

#include <deal.II/distributed/shared_tria.h>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    struct PDLSMFEMModel;
    class JsonWriter;
  } // namespace IO

  namespace Scene
  {
    namespace internal
    {
      /** Everything a run needs, whatever the input format. */
      template <int dim>
      using Setup = RunSetup<dim>;

      /// Wall seconds since @p start.
      inline double
      seconds_since(const std::chrono::steady_clock::time_point &start)
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      }

      /// Create @p out_dir (rank 0), or throw InputError naming @p file and
      /// @p parameter.
      void
      make_output_folder(const std::string &out_dir,
                         const std::string &file,
                         const std::string &parameter,
                         MPI_Comm           comm);


      /// Build the run of a PDLSM-FEM model (pdlsm_fem_scene.cc).
      template <int dim>
      void
      setup_from_pdlsm_fem(const IO::PDLSMFEMModel &model,
                           const RunOptions        &options,
                           MPI_Comm                 comm,
                           Setup<dim>              &setup);

      /// Run a scene with Peridynamics/Model = rnp (rnp_scene.cc): every
      /// vertex an RNP node, Newton driver with the stability check.
      template <int dim>
      int
      execute_rnp(Setup<dim>              &setup,
                  const Parameters::Scene &prm,
                  const RunOptions        &options,
                  MPI_Comm                 comm);

      /// history.csv's first columns of an RNP run: step, time,
      /// load_factor, newton_iterations, linear_iterations, residual,
      /// n_broken_bonds, max_damage, reaction_<set>_<c> for
      /// @p reaction_sets and, with a reaction group, reaction_RF_<c>.
      template <int dim>
      std::vector<std::string>
      base_history_columns(const std::vector<std::string> &reaction_sets,
                           bool                            reaction_group);

      /// summary.json's opening members (Summary::write_header()).
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
        Summary::write_header(
          json, setup, comm, exit_state, message, size, final_size);
      }
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem

#endif
