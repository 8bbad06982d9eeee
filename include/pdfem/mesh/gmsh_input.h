// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_MESH_GMSH_INPUT_H
#define PDFEM_MESH_GMSH_INPUT_H

#include <map>
#include <string>

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
     */
    struct PhysicalNames
    {
      std::map<std::string, unsigned int> regions;
      std::map<std::string, unsigned int> boundaries;

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

    /// Read a gmsh `.msh` file into @p tria (which must be empty).
    template <int dim>
    void
    read_msh(const std::string               &msh_file,
             dealii::Triangulation<dim, dim> &tria);
  } // namespace Mesh
} // namespace pdfem

#endif
