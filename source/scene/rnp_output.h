// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the scene module: the field output of RNP scenes.
#ifndef PDFEM_SOURCE_SCENE_RNP_OUTPUT_H
#define PDFEM_SOURCE_SCENE_RNP_OUTPUT_H

#include <deal.II/grid/tria.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      /**
       * Write @p out_dir/solution-00001.vtu and solution.pvd: the mesh with
       * the nodal displacement, damage and region (1 PD, 2 FE) as point
       * data. @p node_of maps a triangulation vertex to its node; @p u has
       * dim entries per node.
       */
      template <int dim>
      void
      write_rnp_vtu(const std::string                &out_dir,
                    const dealii::Triangulation<dim> &tria,
                    const std::vector<int>           &node_of,
                    const std::vector<double>        &u,
                    const std::vector<double>        &damage,
                    const std::vector<std::uint8_t>  &pd_node,
                    double                            load_factor);
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem

#endif
