// SPDX-License-Identifier: LGPL-2.1-or-later
// The `crack paths` postprocessor.
#include <pdfem/simulator/postprocess.h>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * crack_paths.vtk (legacy VTK polylines, for ParaView) and
       * crack_paths.csv at the end of a run with a crack criterion: the
       * initial cracks, their growth and the virtual cracks.
       */
      template <int dim>
      class CrackPaths : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          return this->get_cracks() != nullptr;
        }

        void
        finish() override
        {
          if (this->is_root())
            this->get_cracks()->write_paths(this->get_output_directory() +
                                              "/crack_paths.vtk",
                                            this->get_output_directory() +
                                              "/crack_paths.csv");
        }
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(CrackPaths,
                                 "crack paths",
                                 "crack_paths.vtk and .csv: initial cracks, "
                                 "their growth and virtual cracks.")
  } // namespace Postprocess
} // namespace pdfem
