// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the scene module: a run set up from any input (a pdfem .prm
// scene or a PDLSM-FEM command file), and the part that executes it.
#ifndef PDFEM_SOURCE_SCENE_SCENE_INTERNAL_H
#define PDFEM_SOURCE_SCENE_SCENE_INTERNAL_H

#include <pdfem/coupling/coupled_system.h>
#include <pdfem/io/parameters.h>
#include <pdfem/scene/scene.h>
#include <pdfem/simulator/simulator.h>

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

    } // namespace internal
  }   // namespace Scene
} // namespace pdfem

#endif
