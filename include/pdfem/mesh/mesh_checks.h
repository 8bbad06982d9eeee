// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_MESH_MESH_CHECKS_H
#define PDFEM_MESH_MESH_CHECKS_H

#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
  template <int dim, typename Number>
  class Point;
  template <int structdim>
  struct CellData;
} // namespace dealii

namespace pdfem
{
  namespace Mesh
  {
    /**
     * The vertices of a cell listed counter-clockwise, as gmsh and
     * PDLSM-FEM list them (quadrilateral 0 1 2 3; hexahedron the bottom
     * face, then the top one), in deal.II's lexicographic order. A cell of
     * @p dim with other than 2^dim vertices (a simplex) is returned as it is.
     */
    template <typename Index>
    std::vector<Index>
    lexicographic_vertex_order(std::vector<Index> v, const unsigned int dim)
    {
      if (v.size() == (1u << dim))
        for (std::size_t face = 0; face < v.size(); face += 4)
          std::swap(v[face + 2], v[face + 3]);
      return v;
    }

    /**
     * Check that @p msh_file is a well-formed ASCII gmsh mesh (format 2.2 or
     * 4.1) before any reader sees it: every section closed where its counts
     * say, each line with the number of fields its section and element type
     * ask for, numbers that parse and coordinates that are finite, node tags
     * unique and within the declared range, every element node a node of
     * `$Nodes`, and the cells of the mesh's dimension neither tangled nor
     * degenerate (as check_cell_shapes(); inverted ones are left to the
     * reader, which turns them round). deal.II's GridIn::read_msh trusts
     * these: it corrupted memory on a truncated or miscounted 4.1 file
     * (issue 19: 26 of 160 mutated files aborted) and looped forever on a
     * tangled quadrilateral (found by fuzzing); binary files are refused.
     *
     * @throws pdfem::InputError naming @p msh_file, the line ("line N") and
     * what was expected there.
     */
    void
    check_msh_file(const std::string &msh_file);

    /**
     * Check the shape of every cell of @p tria (as read, before refinement):
     * the Jacobian at each vertex of a quadrilateral or hexahedron (once for
     * a simplex) must have one sign over the cell and a magnitude above
     * 1e-10 of the cell's longest edge to the power dim. Catches repeated
     * vertices and vertices moved onto others (degenerate) and self-
     * intersecting cells such as a bow-tie quadrilateral (tangled), which
     * otherwise give results off by percent to orders of magnitude without
     * a warning. A cell inverted as a whole is left to the reader (deal.II
     * reorients it).
     *
     * @throws pdfem::InputError naming @p file, "cell N" (the reader's
     * order, from 1) with its vertices, and the problem.
     */
    template <int dim>
    void
    check_cell_shapes(const dealii::Triangulation<dim, dim> &tria,
                      const std::string                     &file);

    /**
     * The same checks on cells not yet made into a triangulation: @p cells
     * (vertex indices into @p vertices, in deal.II's order), numbered "cell
     * N" in the order of the vector. Call it before anything that needs
     * sound cells: deal.II 9.4's GridTools::consistently_order_cells()
     * loops forever on a tangled quadrilateral (found by the .in/.lis fuzz
     * target).
     */
    template <int dim>
    void
    check_cell_shapes(const std::vector<dealii::Point<dim, double>> &vertices,
                      const std::vector<dealii::CellData<dim>>      &cells,
                      const std::string                             &file);
  } // namespace Mesh
} // namespace pdfem

#endif
