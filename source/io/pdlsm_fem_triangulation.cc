// SPDX-License-Identifier: LGPL-2.1-or-later
// The cells of a PDLSM-FEM mesh (specs/004 §1.4, §4.2) as a deal.II
// triangulation.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/io/pdlsm_fem_input.h>
#include <pdfem/mesh/mesh_checks.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

namespace pdfem
{
  namespace IO
  {
    namespace
    {
      InputError
      cannot_build(const PDLSMFEMModel &model)
      {
        return InputError(model.mesh_file,
                          "elements",
                          "deal.II cannot build a mesh from these elements",
                          "conforming, non-inverted Q4/T3 (2D) or H8/T4 "
                          "(3D) elements");
      }
    } // namespace

    template <int dim>
    void
    create_triangulation(const PDLSMFEMModel             &model,
                         dealii::Triangulation<dim, dim> &tria)
    {
      using namespace dealii;
      std::vector<Point<dim>> vertices(model.nodes.size());
      for (std::size_t k = 0; k < model.nodes.size(); ++k)
        for (unsigned int d = 0; d < dim; ++d)
          vertices[k][d] = model.nodes[k][d];
      std::vector<CellData<dim>> cells(model.elements.size());
      bool                       hypercubes_only = true;
      for (std::size_t e = 0; e < model.elements.size(); ++e)
        {
          cells[e].vertices =
            Mesh::lexicographic_vertex_order(model.elements[e].vertices, dim);
          cells[e].material_id = model.elements[e].type; // 1 PD, 2 FE
          hypercubes_only =
            hypercubes_only &&
            cells[e].vertices.size() == GeometryInfo<dim>::vertices_per_cell;
        }
      try
        {
          if (hypercubes_only)
            GridTools::invert_all_negative_measure_cells(vertices, cells);
        }
      catch (const std::exception &)
        {
          throw cannot_build(model);
        }
      // Sound cells first: consistently_order_cells() loops forever on a
      // tangled quadrilateral (a fuzzer's find, tests/fuzz/crashes).
      Mesh::check_cell_shapes(vertices, cells, model.mesh_file);
      try
        {
          if (hypercubes_only)
            GridTools::consistently_order_cells(cells);
          tria.create_triangulation(vertices, cells, SubCellData());
        }
      catch (const std::exception &)
        {
          throw cannot_build(model);
        }
      Mesh::check_cell_shapes(tria, model.mesh_file);
    }

#define INSTANTIATE(dim)                                         \
  template void create_triangulation<dim>(const PDLSMFEMModel &, \
                                          dealii::Triangulation<dim, dim> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace IO
} // namespace pdfem
