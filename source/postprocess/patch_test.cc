// SPDX-License-Identifier: LGPL-2.1-or-later
// The `patch test` postprocessor: the PD-FE coupling's patch test.
#include <pdfem/base/json_writer.h>
#include <pdfem/simulator/postprocess.h>

#include <ostream>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * Coupling::CoupledSystem::patch_test() once, before the driver runs
       * (Output/Patch test: auto runs it for pairwise models, whose
       * coupling by shared nodes is not exact, when there are FE cells):
       * summary.json "patch_test" (strain modes, held nodes, the largest
       * error relative to the affine field, the largest ghost force
       * relative to |sigma| h^(dim-1)) and a line of progress.
       */
      template <int dim>
      class PatchTestOutput : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          const std::string &when = this->get_setup().patch_test;
          if (when == "false" ||
              (when == "auto" &&
               !this->get_system().pd_model().layout().pairwise))
            return false;
          result = this->get_mutable_system().patch_test();
          if (result.strain_modes == 0)
            return false;
          if (std::ostream *out = this->get_progress_stream())
            *out << "  patch test of the coupling (" << result.strain_modes
                 << " strain modes, " << result.held_nodes
                 << " nodes held): max error " << result.max_relative_error
                 << " of the affine field, ghost force "
                 << result.max_relative_ghost_force << " sigma h^(d-1)"
                 << std::endl;
          return true;
        }

        void
        write_sections(IO::JsonWriter &json) const override
        {
          json.begin_object("patch_test");
          json.value("strain_modes",
                     static_cast<unsigned long>(result.strain_modes));
          json.value("held_nodes",
                     static_cast<unsigned long>(result.held_nodes));
          json.value("max_relative_error", result.max_relative_error);
          json.value("max_relative_ghost_force",
                     result.max_relative_ghost_force);
          json.end_object();
        }

      private:
        Coupling::PatchTest result;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(
      PatchTestOutput,
      "patch test",
      "the PD-FE coupling's patch test before the run (Output/Patch test).")
  } // namespace Postprocess
} // namespace pdfem
