// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_MESH_GMSH_INPUT_H
#define PDFEM_MESH_GMSH_INPUT_H

#include <map>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pdfem
{
  namespace Mesh
  {
    /**
     * The named physical groups of a gmsh mesh: name -> tag, separately for
     * the regions (groups of dimension dim, which deal.II turns into material
     * ids) and the boundaries (dimension dim-1, boundary ids). deal.II 9.4's
     * GridIn does not expose the names, so they are read from the
     * `$PhysicalNames` section (identical in formats 2.2 and 4.1).
     * Groups of dimension 0 (physical points) are node sets: see
     * read_node_sets().
     */
    struct PhysicalNames
    {
      std::map<std::string, unsigned int> regions;
      std::map<std::string, unsigned int> boundaries;
      std::map<std::string, unsigned int> node_sets;

      /// "a, b, c": for error messages.
      static std::string
      list(const std::map<std::string, unsigned int> &names);
    };

    /// Read the `$PhysicalNames` of a `.msh` file for a mesh of dimension @p
    /// dim.
    PhysicalNames
    read_physical_names(const std::string &msh_file, int dim);

    /**
     * Return a `.msh` file for @p input: the file itself if it is a `.msh`,
     * or the mesh that the gmsh executable makes of a `.geo` script, written
     * into @p work_dir. Throws InputError (naming @p prm_file and
     * @p parameter) if the file is missing or gmsh fails.
     */
    std::string
    prepare_msh_file(const std::string &input,
                     int                dim,
                     double             size_factor,
                     const std::string &work_dir,
                     const std::string &prm_file,
                     const std::string &parameter);

    /**
     * Read a gmsh `.msh` file into @p tria (which must be empty) with
     * deal.II's GridIn. Call check_msh_file() first: GridIn trusts the
     * file's counts. @throws pdfem::InputError naming @p msh_file with
     * deal.II's reason as one line.
     */
    template <int dim>
    void
    read_msh(const std::string               &msh_file,
             dealii::Triangulation<dim, dim> &tria);

    /**
     * The node sets of a gmsh mesh: every named physical group of dimension 0
     * (elements of type 15, one node each), as vertex indices of @p tria (the
     * mesh read from the same file), in the order of the file. deal.II's
     * GridIn skips these elements in 2D and 3D, so they are read here and
     * matched to the vertices by their coordinates. Such groups can hold any
     * nodes of the mesh, interior ones included.
     *
     * Read from ASCII formats 2.2 and 4.1 (in 4.1, the physical tags of
     * the point entities in `$Entities`).
     * @throws pdfem::InputError (naming @p msh_file) if a file with node sets
     * is in another format, or if a node of a set is no vertex of a cell.
     */
    template <int dim>
    std::map<std::string, std::vector<unsigned int>>
    read_node_sets(const std::string                     &msh_file,
                   const dealii::Triangulation<dim, dim> &tria);
  } // namespace Mesh
} // namespace pdfem

#endif
