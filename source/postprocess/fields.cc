// SPDX-License-Identifier: LGPL-2.1-or-later
// The `fields` postprocessor: VTU/PVTU/PVD output.
#include <pdfem/io/field_output.h>
#include <pdfem/simulator/postprocess.h>

#include <memory>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * solution-NNNNN.vtu/.pvtu and solution.pvd (IO::FieldOutput):
       * displacement, stress, principal stress, damage and region, at the
       * steps of `Output/Write every` and at the last one.
       */
      template <int dim>
      class Fields : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          const auto &setup = this->get_setup();
          if (!setup.write_vtu)
            return false;
          const auto &material = setup.settings.material;
          output =
            std::make_unique<IO::FieldOutput<dim>>(setup.out_dir,
                                                   dim == 2 &&
                                                     !material.plane_stress,
                                                   material.poissons_ratio);
          return true;
        }

        void
        write_fields(const double t) override
        {
          output->write(this->get_system(), this->get_nodal_results(), t);
        }

        void
        finish() override
        {
          output->finish();
        }

        void
        save_state(StateArchive &state) override
        {
          output->save_state(state);
        }

        void
        load_state(const StateArchive &state) override
        {
          output->load_state(state);
        }

      private:
        std::unique_ptr<IO::FieldOutput<dim>> output;
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(Fields,
                                 "fields",
                                 "VTU/PVTU/PVD fields (Output/Write vtu, "
                                 "Write every).")
  } // namespace Postprocess
} // namespace pdfem
