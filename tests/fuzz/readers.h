// SPDX-License-Identifier: LGPL-2.1-or-later
// The input readers as fuzz targets (doc/reliability.md, "Fuzzing"): each
// takes the bytes of one input, writes them to a file in a scratch folder and
// reads it as pdfem does before any work. Bad input must end in one
// pdfem::InputError with a one-line message; anything else (another exception,
// an empty or multi-line message, a crash) aborts, which libFuzzer and the
// corpus replay (ctest fuzz.*) report as a failure.
#ifndef PDFEM_TESTS_FUZZ_READERS_H
#define PDFEM_TESTS_FUZZ_READERS_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace pdfem
{
  namespace Fuzz
  {
    /// How an input ended: read, or refused with an InputError.
    enum class Outcome
    {
      accepted,
      refused
    };

    /**
     * A parameter file (.prm): Parameters::Scene::read() and make_plugins()
     * for its dimension (every plugin reads its own parameters).
     */
    Outcome
    read_prm(const std::uint8_t *data, std::size_t size);

    /**
     * A gmsh mesh (.msh): Mesh::check_msh_file(), then, as a mesh of
     * dimension 2 and of dimension 3, the physical names, deal.II's reader,
     * the cell-shape checks and the node sets.
     */
    Outcome
    read_msh(const std::uint8_t *data, std::size_t size);

    /**
     * A PDLSM-FEM command file (.in) with its mesh (.lis): the bytes up to a
     * line `#@ mesh` are the command file `fuzz.in`, those after it the
     * file `mesh.lis` (which the command file's MSHFILE names, or not);
     * IO::read_pdlsm_fem(), then IO::create_triangulation().
     */
    Outcome
    read_pdlsm_fem(const std::uint8_t *data, std::size_t size);

    /// The reader called @p name (prm, msh, pdlsm_fem); nullptr if none.
    using Reader = Outcome (*)(const std::uint8_t *, std::size_t);
    Reader
    reader(const std::string &name);
  } // namespace Fuzz
} // namespace pdfem

#endif
