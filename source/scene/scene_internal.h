// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the scene module: a run set up from any input (a pdfem .prm
// scene or a PDLSM-FEM command file), and the part that executes it.
#ifndef PDFEM_SOURCE_SCENE_SCENE_INTERNAL_H
#define PDFEM_SOURCE_SCENE_SCENE_INTERNAL_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/drivers/dynamics.h>
#include <pdfem/io/parameters.h>
#include <pdfem/scene/scene.h>

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
      struct Setup
      {
        std::string file;    // the input file, for messages and summary.json
        std::string name;    // its stem
        std::string out_dir; // created already
        std::unique_ptr<dealii::parallel::shared::Triangulation<dim>> tria;
        std::vector<bool>       cell_is_pd;
        Coupling::Settings<dim> settings;
        Parameters::Driver      driver;
        Parameters::Fracture    fracture;
        /// Which end of each initial crack is its tip (empty: every end
        /// inside the body that touches no other crack).
        std::vector<bool> tip_at_end;
        bool              write_vtu = true;
        /// Field output every this many steps (and at the last); 0: last.
        unsigned int write_every     = 0;
        bool         write_nodes_csv = false;
        bool         print_timings   = false;
        /// Dirichlet sets whose reactions are also summed as "RF" (the
        /// reaction-force sets of a PDLSM-FEM command file).
        std::vector<unsigned int> reaction_group;
        /// Remarks printed on stderr before the run (unsupported options
        /// that do not change the result, and the like).
        std::vector<std::string> notes;
        /// Dynamic runs: builds the optional after-step hook (a fracture
        /// criterion that may break bonds; returns whether any broke) once
        /// the coupled system exists. Empty: no bond breaks.
        std::function<Drivers::AfterStep(Coupling::CoupledSystem<dim> &)>
                                              make_after_step;
        std::map<std::string, double>         timings;
        std::chrono::steady_clock::time_point total_start;
        std::chrono::steady_clock::time_point setup_start;
      };

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

      /// An empty shared triangulation partitioned by METIS.
      template <int dim>
      std::unique_ptr<dealii::parallel::shared::Triangulation<dim>>
      make_triangulation(MPI_Comm comm);

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

      /// A dynamic run (Driver/Type = explicit or newmark; dynamic_run.cc):
      /// the coupled system, the time integrator, history.csv with the
      /// energy balance, VTU and summary.json.
      template <int dim>
      int
      execute_dynamic(Setup<dim>       &setup,
                      const RunOptions &options,
                      MPI_Comm          comm);

      /// history.csv's first columns, the same for every driver: step,
      /// time, load_factor, newton_iterations, linear_iterations,
      /// residual, n_broken_bonds, max_damage, reaction_<set>_<c> for
      /// @p reaction_sets and, with a reaction group, reaction_RF_<c>.
      template <int dim>
      std::vector<std::string>
      base_history_columns(const std::vector<std::string> &reaction_sets,
                           bool                            reaction_group);

      /// The sum of @p reactions over the sets of @p group (PDLSM-FEM's RF).
      template <int dim>
      dealii::Tensor<1, dim>
      group_reaction(const std::vector<dealii::Tensor<1, dim>> &reactions,
                     const std::vector<unsigned int>           &group)
      {
        dealii::Tensor<1, dim> R;
        for (const unsigned int s : group)
          R += reactions[s];
        return R;
      }

      /// summary.json's final extremes of the nodal fields: max and min
      /// displacement and stress per component, max_principal_stress and
      /// max_damage.
      template <int dim>
      void
      write_final_fields(IO::JsonWriter                    &json,
                         const Coupling::NodalResults<dim> &results);

      /// summary.json's "reaction" per set and, with a group, "reaction_RF".
      template <int dim>
      void
      write_final_reactions(
        IO::JsonWriter                            &json,
        const std::vector<std::string>            &names,
        const std::vector<dealii::Tensor<1, dim>> &reactions,
        const std::vector<unsigned int>           &group);

      /// summary.json's opening members: version, scene, input file,
      /// dimension, ranks, threads, exit state, message and the problem sizes
      /// (bonds broken and nodes decoupled from @p final_size).
      template <int dim>
      void
      write_summary_header(IO::JsonWriter              &json,
                           const Setup<dim>            &setup,
                           MPI_Comm                     comm,
                           const std::string           &exit_state,
                           const std::string           &message,
                           const Coupling::ProblemSize &size,
                           const Coupling::ProblemSize &final_size);

      /// Set up the coupled system, run the driver, write every output.
      template <int dim>
      int
      execute(Setup<dim> &setup, const RunOptions &options, MPI_Comm comm);
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem

#endif
