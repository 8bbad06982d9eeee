// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SCENE_CONVERT_H
#define PDFEM_SCENE_CONVERT_H

#include <string>
#include <vector>

#include <mpi.h>

namespace pdfem
{
  namespace Scene
  {
    /** What convert_pdlsm_fem() wrote. */
    struct Conversion
    {
      /// The native scene, `<stem>.prm`.
      std::string prm_file;
      /// Its gmsh mesh (format 2.2 ASCII), `<stem>.msh`.
      std::string msh_file;
      /// Remarks about options that the run ignores in both forms alike
      /// (the notes `pdfem model.in` prints), for stderr.
      std::vector<std::string> notes;
    };

    /**
     * Write the native pdfem scene equivalent to a PDLSM-FEM command file
     * and its `.lis` mesh (specs/004 §4): `<stem>.prm` and `<stem>.msh` in
     * @p output_dir (created if missing), such that `pdfem <stem>.prm` runs
     * what `pdfem <stem>.in` runs.
     *
     * The model is read by IO::read_pdlsm_fem() and set up exactly as for a
     * run (so malformed input gets the reader's messages), then written from
     * that set-up:
     * - the `.lis` nodes and elements in their order, element type 1/2 as the
     *   physical regions `pd`/`fe` (tags 1/2); quads, triangles, hexes and
     *   tetrahedra;
     * - essential set i as the node set (physical point group) `ebc<i>`,
     *   the NO FAIL region as `nofail`, natural set i as the boundary
     *   `nbc<i>` (tag 10 + i);
     * - every parameter the run uses, with 17 significant digits.
     *
     * The `.prm` is then read back and compared with the set-up; anything
     * the `.prm` cannot say throws InputError instead of writing a different
     * scene.
     *
     * @throws pdfem::InputError for bad input (the reader's and the scene's
     * messages) and for what cannot be expressed.
     */
    Conversion
    convert_pdlsm_fem(const std::string &command_file,
                      const std::string &output_dir,
                      MPI_Comm           comm);
  } // namespace Scene
} // namespace pdfem

#endif
